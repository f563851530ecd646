# xsimd is header-only. Two Debian quirks are handled here:
# - the package's exported target links a library `xtl` that does not exist;
# - a cross compiler must not see /usr/include, so it gets a folder holding only an `xsimd` link.
if(CMAKE_CROSSCOMPILING)
  set(_xsimd_dir "${CMAKE_BINARY_DIR}/xsimd-include")
  file(MAKE_DIRECTORY "${_xsimd_dir}")
  file(CREATE_LINK /usr/include/xsimd "${_xsimd_dir}/xsimd" SYMBOLIC)
  add_library(xsimd INTERFACE IMPORTED)
  set_target_properties(xsimd PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_xsimd_dir}")
else()
  if(NOT TARGET xtl)
    add_library(xtl INTERFACE IMPORTED)
  endif()
  find_package(xsimd CONFIG REQUIRED)
endif()
