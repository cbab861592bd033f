# Shared libraries everywhere, static archives in the command line.
#
# A process start maps and relocates every shared library it needs; for a command that
# classifies a few thousand points that is a large share of its run (docs/inside.md, "End
# to end"). So the command line (build/bin/exactgeo) links GMP, MPFR, libpng and zlib from
# their static archives (Debian's -dev packages ship them), while the Python module, the
# tests and the benchmarks link the shared libraries as before. The choice is made per
# linked target: a library links exactgeo_link(<name>), which is the shared library's
# imported target, or the archives when the target being linked has the property
# EXACTGEO_STATIC_LIBRARIES set (exactgeo_link_statically(<target>)).

# exactgeo_find_archives(<variable> <name>...): the paths of lib<name>.a, in order.
function(exactgeo_find_archives variable)
  set(paths "")
  foreach(name IN LISTS ARGN)
    find_library(EXACTGEO_ARCHIVE_${name} NAMES lib${name}.a)
    if(NOT EXACTGEO_ARCHIVE_${name})
      message(FATAL_ERROR "lib${name}.a not found: the command line links it statically "
                          "(Debian: the package with lib${name}.so, -dev; scripts/install-dependencies.sh)")
    endif()
    list(APPEND paths ${EXACTGEO_ARCHIVE_${name}})
  endforeach()
  set(${variable} "${paths}" PARENT_SCOPE)
endfunction()

# For each dependency, the shared target and the archives that stand in for it (an
# archive's own dependencies after it: MPFR needs GMP, libpng zlib).
exactgeo_find_archives(EXACTGEO_GMP_ARCHIVES gmpxx gmp)
exactgeo_find_archives(EXACTGEO_MPFR_ARCHIVES mpfr gmp)
exactgeo_find_archives(EXACTGEO_PNG_ARCHIVES png16 z)

set(EXACTGEO_STATIC_HEAD "$<BOOL:$<TARGET_PROPERTY:EXACTGEO_STATIC_LIBRARIES>>")

# exactgeo_link(<variable> <shared target> <archives variable>): the link item, a generator
# expression read with the target being linked (the head of the link, not the library
# that names the dependency).
# One expression per item, so that the list splits between items only.
function(exactgeo_link variable shared archives)
  set(items "$<$<NOT:${EXACTGEO_STATIC_HEAD}>:${shared}>")
  foreach(archive IN LISTS ${archives})
    list(APPEND items "$<${EXACTGEO_STATIC_HEAD}:${archive}>")
  endforeach()
  set(${variable} "${items}" PARENT_SCOPE)
endfunction()
exactgeo_link(EXACTGEO_LINK_GMP PkgConfig::GMP EXACTGEO_GMP_ARCHIVES)
exactgeo_link(EXACTGEO_LINK_MPFR PkgConfig::MPFR EXACTGEO_MPFR_ARCHIVES)
# PNG::PNG comes from find_package(PNG) in apps/, which names it there.

# exactgeo_link_statically(<target>): <target> gets the archives.
function(exactgeo_link_statically target)
  set_property(TARGET ${target} PROPERTY EXACTGEO_STATIC_LIBRARIES ON)
endfunction()
