# OpenImageIO for the tools, the benchmark's peer and the tests that read or write images (never
# the library). Defines the OpenImageIO::OpenImageIO target when Debian's libopenimageio-dev is
# installed (required under EDGEWISE_STRICT_DEPENDENCIES). Two Debian quirks are handled here:
# - its exported target names /usr/include/opencv4, which does not exist, so that entry is
#   dropped;
# - Imath's CMake package, which it loads, names a Python module library that only
#   python3-imath ships, and says so in a ten-line status message at every configure. Status
#   messages are muted while it loads; warnings and errors still show.
if(TARGET OpenImageIO::OpenImageIO)
  return()
endif()
set(_edgewise_log_level "${CMAKE_MESSAGE_LOG_LEVEL}")
set(CMAKE_MESSAGE_LOG_LEVEL NOTICE)
find_package(OpenImageIO CONFIG QUIET ${EDGEWISE_REQUIRED_IF_STRICT})
set(CMAKE_MESSAGE_LOG_LEVEL "${_edgewise_log_level}")
if(OpenImageIO_FOUND)
  foreach(property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(dirs OpenImageIO::OpenImageIO ${property})
    if(dirs)
      list(FILTER dirs EXCLUDE REGEX "/opencv4$")
      set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${property} "${dirs}")
    endif()
  endforeach()
endif()
