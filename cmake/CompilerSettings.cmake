# Warnings, floating-point hygiene and sanitizers shared by every target.

add_library(exactgeo_warnings INTERFACE)
target_compile_options(exactgeo_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                                   -Wno-sign-conversion)
if(EXACTGEO_WERROR)
  target_compile_options(exactgeo_warnings INTERFACE -Werror)
endif()

# Predicate code relies on every floating-point operation being rounded exactly once, to
# nearest: no fused multiply-add contraction (it breaks the error-free transformations
# and the filter error bounds) and no fast-math. Excess precision (x87) is refused at
# compile time in error_free.hpp (FLT_EVAL_METHOD must be 0).
add_library(exactgeo_strict_fp INTERFACE)
target_compile_options(exactgeo_strict_fp INTERFACE -ffp-contract=off -fno-fast-math)
# The filter constants and certificate bounds are derived at compile time (roundoff.hpp):
# clang's default budget of constexpr steps is too small for the slice-side quartics.
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  target_compile_options(exactgeo_strict_fp INTERFACE -fconstexpr-steps=100000000)
endif()

if(EXACTGEO_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

if(EXACTGEO_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "EXACTGEO_BUILD_FUZZERS needs clang (libFuzzer): CXX=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

# exactgeo_library(<name> [<sources...>]): a library of the current top-level folder, as
# target exactgeo_<name> with alias exactgeo::<name>, public headers in <folder>/include;
# header-only (an INTERFACE library) when no source is given. (One library per folder,
# named after it; mesh/ has a second one, mesh_files.)
function(exactgeo_library name)
  set(target exactgeo_${name})
  if(ARGN)
    add_library(${target} ${ARGN})
    set(scope PUBLIC)
    set_target_properties(${target} PROPERTIES OUTPUT_NAME ${target})
    # Build-only: the warnings (and -Werror) are ours, not an installed consumer's.
    target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:exactgeo_warnings>)
    # Position-independent code (the libraries are built so when the Python module links
    # them) lets GCC assume that any function with external linkage may be replaced at
    # load time, and so it neither inlines nor calls directly a function defined in the
    # same file; the command line paid for that in its per-point calls. Nothing of ours is
    # meant to be replaced at load time (the libraries are static by default), so the
    # assumption buys nothing.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -fno-semantic-interposition)
    endif()
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_library(exactgeo::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:include>)
  target_compile_features(${target} ${scope} cxx_std_20)
endfunction()
