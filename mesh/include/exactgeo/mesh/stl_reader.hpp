#pragma once

// STL (stereolithography), ASCII and binary, read exactly.
//
// Binary: an 80-byte header (any bytes; many writers start it with "solid"), the triangle
// count n (uint32, little-endian), then n records of 50 bytes: the normal (3 float32), the
// three corners (3 float32 each) and a uint16 attribute. The file has exactly 84 + 50 n
// bytes. Each float32 widens to double exactly, so coordinates keep every bit. Normals and
// attributes are not used.
//
// ASCII:
//     solid [name]
//       facet normal nx ny nz
//         outer loop
//           vertex x y z        (three times)
//         endloop
//       endfacet
//       ...
//     endsolid [name]
// and more such solids may follow (some exporters write one per part). Keywords are read
// in any case; they and the numbers may be spread over the lines in any way, but a solid's
// name is the rest of its line. Coordinates are decimal (or hexadecimal) literals converted
// with correct rounding, as in OBJ: a coordinate copied from the file reads back exactly.
// A normal is three floats as a writer prints them, and normals are not used: any number
// literal is taken (even beyond the double range), and so is every spelling of NaN and
// infinity that C runtimes print (some writers put them on degenerate facets): glibc's and
// current MSVC's "nan", "-inf", "-nan(ind)", "nan(chars)", older MSVC's "1.#INF00",
// "-1.#IND00", "1.#QNAN0", "1.#SNAN" (and "1.#INF00e+000" from %e), Java's "Infinity", in
// any case. A token that is no float ("a", "1,5", "0x") is refused. A UTF-8 byte order mark is
// skipped.
//
// Which of the two a file is: binary when its size is exactly 84 + 50 n for the count n in
// bytes 80..83, unless it begins with "solid" and reads as ASCII STL to its end. (Text in
// bytes 80..83 declares at least 0x09090909 triangles, a file of over 7.5 GB; binary files
// whose header begins with "solid" are common.) Any other size: ASCII when it begins with
// "solid" (after blanks, in any case) and holds no NUL byte, which text never does and
// binary data nearly always does (the attribute is 0); else binary, so that a truncated
// binary file, or one with bytes after its last triangle, is reported as such.
//
// STL stores a triangle soup, each facet with its own three corners: the reader always
// welds vertices at exactly the same position (weld_vertices: +0 and -0 are equal) and
// says how many it merged in LoadedMesh::welded_vertices. Facets with repeated corners are
// kept, for the mesh checks to report.

#include <string>
#include <string_view>

#include "exactgeo/mesh/loaded_mesh.hpp"

namespace exactgeo::mesh {

/// Parses STL data, binary or ASCII (format "stl binary" or "stl ascii"); `source` names
/// it in errors: "<source>:<line>: ..." for ASCII, "<source>: triangle <index>: ..." for
/// binary. Every facet is a triangle, so options.split_polygons has nothing to do; the
/// vertices are always welded (options.weld or not). A file without facets is an error.
/// Throws io::InputError.
LoadedMesh read_stl(std::string_view bytes, const std::string& source, const LoadOptions& options);

}  // namespace exactgeo::mesh
