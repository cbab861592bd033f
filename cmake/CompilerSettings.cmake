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

# exactgeo_library(<folder> <sources...>): the library of one top-level folder, as target
# exactgeo_<folder> with alias exactgeo::<folder>, public headers in <folder>/include.
function(exactgeo_library folder)
  set(target exactgeo_${folder})
  add_library(${target} ${ARGN})
  add_library(exactgeo::${folder} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${folder} OUTPUT_NAME ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:include>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  # Build-only: the warnings (and -Werror) are ours, not an installed consumer's.
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:exactgeo_warnings>)
endfunction()
