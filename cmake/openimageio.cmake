# OpenImageIO for the tools, the benchmark's peer and the tests that read or write images (never
# the library). Defines the OpenImageIO::OpenImageIO target when Debian's libopenimageio-dev is
# installed; its exported target names /usr/include/opencv4, which does not exist, so that
# entry is dropped.
if(TARGET OpenImageIO::OpenImageIO)
  return()
endif()
find_package(OpenImageIO CONFIG QUIET)
if(OpenImageIO_FOUND)
  foreach(property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(dirs OpenImageIO::OpenImageIO ${property})
    if(dirs)
      list(FILTER dirs EXCLUDE REGEX "/opencv4$")
      set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${property} "${dirs}")
    endif()
  endforeach()
endif()
