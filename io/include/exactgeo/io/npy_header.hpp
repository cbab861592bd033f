#pragma once

// The header of a NumPy .npy file (format versions 1.0, 2.0 and 3.0), for the one kind of
// array exactgeo reads: float64 points, shape (n, 3), in C order, little- or big-endian.
//
//   "\x93NUMPY" major minor  header_len  dict (padding) '\n'  data...
//
// header_len is a little-endian uint16 (version 1) or uint32 (2 and 3); dict is a Python
// literal, as np.save writes it: {'descr': '<f8', 'fortran_order': False, 'shape': (1000, 3), }.
// The dict is parsed strictly (exactly those three keys, each once; Python string, bool and
// tuple syntax) but any whitespace, key order and trailing commas are accepted.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace exactgeo::io {

/// What an .npy header says about the float64 (n, 3) array after it.
struct NpyPoints {
  std::uint64_t points = 0;     ///< n, the number of rows
  bool big_endian = false;      ///< descr '>f8' (else '<f8')
  std::size_t data_offset = 0;  ///< the header's size: the offset of the first data byte
};

/// Bytes enough for npy_header_size: the magic string, the version and the length.
inline constexpr std::size_t kNpyPreambleBytes = 12;

/// The largest header accepted (numpy itself refuses more than 10,000 bytes by default; a
/// (n, 3) array's header takes 128).
inline constexpr std::size_t kNpyMaxHeaderBytes = std::size_t{1} << 16;

/// The size of the whole header (preamble and dict) from the file's first bytes: at least
/// kNpyPreambleBytes of them, or all of a shorter file. Throws InputError
/// ("<source>: header: ...") for a wrong magic string, an unknown version, a length beyond
/// kNpyMaxHeaderBytes, or a file that ends within the preamble.
std::size_t npy_header_size(std::string_view first_bytes, const std::string& source);

/// Parses the header at the start of `bytes`, which holds all of it (what follows is not
/// read). Anything but a C-order float64 (n, 3) array is refused with a message saying what
/// was found and what is accepted. Throws InputError ("<source>: header: ...").
NpyPoints parse_npy_header(std::string_view bytes, const std::string& source);

}  // namespace exactgeo::io
