# GESMI_STATIC_ARCHIVES=ON links the gesmi command with the static archives Debian ships
# in the same -dev packages (same versions) instead of the shared libraries: the linker
# takes only the objects gesmi calls, and --as-needed drops the shared libraries nothing
# refers to any more. It saves the loader's work at each start (Debian's shared HDF5
# loads libcurl and its ~25 libraries, cairo X11's): about 11 ms of CPU per command,
# which matters only to scripts that run the command thousands of times. Off by default:
# a program linked against the shared libraries gets their security updates.
# The Python module and the tests always keep the shared libraries (a static HDF5 next to
# h5py's shared one in one process would be two HDF5 libraries).
option(GESMI_STATIC_ARCHIVES "link the gesmi command with the static archives of its dependencies" OFF)

# gesmi_link_static_archives(<target> <shared libraries the target links when OFF>...)
function(gesmi_link_static_archives target)
  target_include_directories(${target} SYSTEM PRIVATE ${Boost_INCLUDE_DIRS})
  if(NOT GESMI_STATIC_ARCHIVES)
    target_link_libraries(${target} PRIVATE ${ARGN})
    return()
  endif()
  find_package(Threads REQUIRED)
  get_filename_component(hdf5_dir "${HDF5_C_LIBRARY_hdf5}" DIRECTORY)
  # In link order: each archive before the libraries it calls.
  set(entries "boost_program_options" "hdf5:${hdf5_dir}" "yaml-cpp" "GeographicLib" "cairo" "pixman-1" "fontconfig"
              "freetype" "png16" "brotlidec" "brotlicommon" "bz2" "expat" "crypto" "sz" "aec" "z")
  # Fonts and compression stay shared under the sanitizers, whose leak suppression names
  # libfontconfig.so (docs/testing.md).
  set(shared_under_sanitizers "fontconfig" "freetype" "brotlidec" "brotlicommon" "bz2" "expat" "sz" "aec" "z")
  if(GESMI_SANITIZE)
    list(REMOVE_ITEM entries ${shared_under_sanitizers})
  endif()
  set(archives)
  foreach(entry IN LISTS entries)
    string(REPLACE ":" ";" parts "${entry}")
    list(GET parts 0 name)
    list(LENGTH parts count)
    set(hints)
    if(count GREATER 1)
      list(GET parts 1 hints)
    endif()
    find_library(GESMI_ARCHIVE_${name} NAMES lib${name}.a HINTS ${hints} NO_CMAKE_SYSTEM_PATH)
    if(NOT GESMI_ARCHIVE_${name})
      find_library(GESMI_ARCHIVE_${name} NAMES lib${name}.a HINTS ${hints})
    endif()
    if(NOT GESMI_ARCHIVE_${name})
      message(FATAL_ERROR "lib${name}.a not found: run tools/install_deps.sh, or configure with -DGESMI_STATIC_ARCHIVES=OFF")
    endif()
    list(APPEND archives ${GESMI_ARCHIVE_${name}})
  endforeach()
  target_link_options(${target} PRIVATE -Wl,--as-needed)
  target_link_libraries(${target} PRIVATE ${archives} ${CMAKE_DL_LIBS} Threads::Threads)
  # The C++ runtime static too, except under the sanitizers (theirs replaces the C++
  # allocation functions), where fonts and compression stay shared as well.
  if(GESMI_SANITIZE)
    pkg_check_modules(GESMI_FONTS REQUIRED IMPORTED_TARGET fontconfig freetype2)
    target_link_libraries(${target} PRIVATE ${HDF5_C_LIBRARY_sz} PkgConfig::GESMI_FONTS ${HDF5_C_LIBRARY_z})
  else()
    target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc)
  endif()
endfunction()
