# The include rules of docs/architecture.md, checked on the sources (ctest
# architecture.includes):
#
#   cmake -DROOT=<source tree> -P cmake/CheckArchitecture.cmake
#
# 1. A library includes public headers only of the libraries below it (kAllowed below);
#    apps/, examples/ and python/ may include every library's public headers.
# 2. A library's internal/ headers are included only by that library's own files, its own
#    tests (tests/<library>/) and the benchmarks (bench/ measures internals on purpose).
# 3. Inside ccd/, a file of one room includes headers of its own room and of the rooms below
#    it only (kCcdRoomOrder below), so that no two rooms depend on each other; every file
#    of ccd/ is in a room.
# 4. testbed/ (what the tests and the benchmarks generate and measure) is included only by
#    tests/ and bench/: no library, no app, no Python module depends on it.
#
# Every violation is listed with its file and line; any violation fails the run.

cmake_minimum_required(VERSION 3.22)

if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P CheckArchitecture.cmake")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)

# What each library may include besides itself (its targets' dependencies). ccd_files is
# the one room of ccd/ that is a library of its own (src/files/, include/exactgeo/ccd/files/):
# CCD reads no files, so only it may include io.
set(kLibraries predicates parallel io boxes surface mesh ccd ccd_files inside remesh testbed)
set(kAllowed_predicates "")
set(kAllowed_parallel "")
set(kAllowed_io "")
set(kAllowed_boxes predicates)
set(kAllowed_surface predicates)
set(kAllowed_mesh predicates io boxes surface parallel)
set(kAllowed_ccd predicates boxes surface parallel)
set(kAllowed_ccd_files ccd predicates surface io)
set(kAllowed_inside predicates boxes surface mesh parallel)
set(kAllowed_remesh predicates boxes surface ccd mesh)
set(kAllowed_testbed "")

# The rooms of ccd/ (docs/architecture.md, "ccd/"), lowest first; rooms between the same
# two "<" are peers and may not include each other. common holds what every room speaks
# and shares; dispatch (ccd.hpp) chooses among the methods of pair, separation and
# baselines; mesh runs the dispatch on pairs of a mesh; files is exactgeo::ccd_files.
set(kCcdRoomOrder "common < pair, separation, baselines < dispatch < mesh, files")
# A room's files are ccd/src/<room>/ and ccd/include/exactgeo/ccd/<room>/, except pair's,
# which has the top of include/exactgeo/ccd/: its internal/ and the public headers listed
# here, with the other rooms' public headers that keep a short name (ccd.hpp is the
# dispatch's). A header at the top that no list names is in no room.
set(kCcdTopHeaders_common queries.hpp result.hpp)
set(kCcdTopHeaders_pair root_parity.hpp)
set(kCcdTopHeaders_dispatch ccd.hpp)

set(kCcdRooms "")
string(REPLACE "<" ";" levels "${kCcdRoomOrder}")
set(level 0)
foreach(peers IN LISTS levels)
  string(REPLACE "," ";" peers "${peers}")
  foreach(room IN LISTS peers)
    string(STRIP "${room}" room)
    list(APPEND kCcdRooms ${room})
    set(kCcdLevel_${room} ${level})
  endforeach()
  math(EXPR level "${level} + 1")
endforeach()

# The room of a file of ccd/, given by its path inside ccd/ (src/pair/x.cpp,
# include/exactgeo/ccd/internal/y.hpp); "" for a file in no room.
function(ccd_room_of path out)
  set(room "")
  if(path MATCHES "^(src|include/exactgeo/ccd)/([a-z_]+)/")
    if(CMAKE_MATCH_2 IN_LIST kCcdRooms)
      set(room "${CMAKE_MATCH_2}")
    elseif(CMAKE_MATCH_1 STREQUAL "include/exactgeo/ccd" AND CMAKE_MATCH_2 STREQUAL "internal")
      set(room pair)
    endif()
  elseif(path MATCHES "^include/exactgeo/ccd/([^/]+)$")
    foreach(candidate IN LISTS kCcdRooms)
      if(CMAKE_MATCH_1 IN_LIST kCcdTopHeaders_${candidate})
        set(room "${candidate}")
      endif()
    endforeach()
  endif()
  set(${out} "${room}" PARENT_SCOPE)
endfunction()

set(violations "")

# The folder a file belongs to (predicates, ccd, ..., tests/<x>, bench, apps, python).
function(owner_of relative out)
  string(REGEX MATCH "^[^/]+" top "${relative}")
  if(top STREQUAL "tests")
    string(REGEX MATCH "^tests/[^/]+" top "${relative}")
  elseif(relative MATCHES "^ccd/(src/files|include/exactgeo/ccd/files)/")
    set(top "ccd_files")
  endif()
  set(${out} "${top}" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE sources RELATIVE "${ROOT}" "${ROOT}/*.hpp" "${ROOT}/*.cpp")
foreach(relative IN LISTS sources)
  if(relative MATCHES "^build" OR relative MATCHES "^tests/architecture/")
    continue()
  endif()
  owner_of("${relative}" owner)
  set(room "")
  if(owner STREQUAL "ccd" OR owner STREQUAL "ccd_files")
    string(REGEX REPLACE "^ccd/" "" inside_ccd "${relative}")
    ccd_room_of("${inside_ccd}" room)
    if(room STREQUAL "")
      list(APPEND violations "${relative}: is in no room of ccd")
    endif()
  endif()
  file(STRINGS "${ROOT}/${relative}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]exactgeo/")
  file(READ "${ROOT}/${relative}" content)
  foreach(line IN LISTS lines)
    string(REGEX MATCH "exactgeo/([a-z_]+)/" _ "${line}")
    set(library "${CMAKE_MATCH_1}")
    if(line MATCHES "exactgeo/ccd/files/")
      set(library "ccd_files")
    endif()
    if(NOT library IN_LIST kLibraries)
      continue()  # exactgeo/version.hpp (generated for apps/) and the like
    endif()
    # The line number: one more than the newlines before the include.
    string(FIND "${content}" "${line}" position)
    string(SUBSTRING "${content}" 0 ${position} before)
    string(REGEX MATCHALL "\n" newlines "${before}")
    list(LENGTH newlines line_number)
    math(EXPR line_number "${line_number} + 1")
    set(where "${relative}:${line_number}")
    # Rule 2: internal/ headers (at any depth: exactgeo/ccd/mesh/internal/) stay with their
    # library.
    if(line MATCHES "exactgeo/${library}/([a-z_]+/)*internal/")
      if(NOT (owner STREQUAL library OR owner STREQUAL "tests/${library}" OR owner STREQUAL "bench"))
        list(APPEND violations "${where}: ${owner} includes an internal header of ${library}: ${line}")
      endif()
    endif()
    # Rule 1: a library includes only what lies below it.
    if(owner IN_LIST kLibraries AND NOT owner STREQUAL library)
      if(NOT library IN_LIST kAllowed_${owner})
        list(APPEND violations "${where}: ${owner} may not include ${library}: ${line}")
      endif()
    endif()
    # Rule 4: testbed stays with the tests and the benchmarks.
    if(library STREQUAL "testbed" AND NOT owner MATCHES "^(tests/.*|bench|testbed)$")
      list(APPEND violations "${where}: ${owner} may not include testbed (tests and benchmarks only): ${line}")
    endif()
    # Rule 3: a room of ccd includes only its own room and the rooms below it.
    if(NOT room STREQUAL "" AND (library STREQUAL "ccd" OR library STREQUAL "ccd_files"))
      string(REGEX MATCH "exactgeo/ccd/[^\">]+" header "${line}")
      ccd_room_of("include/${header}" included)
      if(included STREQUAL "")
        list(APPEND violations "${where}: ccd room ${room} includes a header in no room: ${line}")
      elseif(NOT included STREQUAL room AND NOT kCcdLevel_${included} LESS kCcdLevel_${room})
        list(APPEND violations
             "${where}: ccd room ${room} may not include room ${included}: ${line}")
      endif()
    endif()
  endforeach()
endforeach()

if(violations)
  list(LENGTH violations count)
  string(REPLACE ";" "\n  " listed "${violations}")
  message(FATAL_ERROR "${count} include rule violation(s) (docs/architecture.md; the rooms of "
                      "ccd, lowest first: ${kCcdRoomOrder}):\n  ${listed}")
endif()
message(STATUS "include rules hold")
