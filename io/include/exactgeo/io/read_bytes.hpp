#pragma once

// Whole files and streams into memory: the mesh readers parse from a byte buffer, which
// lets them check every declared count against the bytes that are really there.

#include <istream>
#include <string>

namespace exactgeo::io {

/// The file's bytes; throws InputError naming the file when it cannot be opened or read.
std::string read_file(const std::string& path);

/// Throws InputError naming the file when it cannot be opened for reading.
void require_readable(const std::string& path);

/// The rest of the stream's bytes; throws InputError naming `source` on a read error.
std::string read_stream(std::istream& in, const std::string& source);

}  // namespace exactgeo::io
