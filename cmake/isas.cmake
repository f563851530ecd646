# The instruction sets edgewise compiles its kernels for, and how. This list and
# kernels/core/isa_list.hpp are the only places that name them; tests/core/isa_dispatch_test.cpp fails
# if the two disagree. Adding an ISA: its entry here (name and compiler flags), its entry in
# isa_list.hpp (xsimd architecture and CPU check) and its value in the Isa enum
# (kernels/include/edgewise/isa.hpp).
#
# EDGEWISE_ISAS: the ISAs of the target processor, worst first (the scalar reference, which
# every build has, is not among them). EDGEWISE_ISA_FLAGS_<isa>: that ISA's compiler flags.
# EDGEWISE_ISAS_OF_OTHER_PROCESSORS: the rest, which the tests check are refused here.
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(EDGEWISE_ISAS sse2 sse4_1 avx2 avx512)
  # The SSE objects must not contain VEX code (tools/check_isa_objects.sh checks it).
  set(EDGEWISE_ISA_FLAGS_sse2 -msse2 -mno-sse3 -mno-avx)
  set(EDGEWISE_ISA_FLAGS_sse4_1 -msse4.1 -mno-avx)
  set(EDGEWISE_ISA_FLAGS_avx2 -mavx2 -mfma)
  # AVX-512 F, CD, DQ, BW and VL: the subset of Intel Skylake-SP and later and of AMD Zen 4 and later.
  set(EDGEWISE_ISA_FLAGS_avx512 -mavx2 -mfma -mavx512f -mavx512cd -mavx512dq -mavx512bw -mavx512vl)
  # GCC 12's AVX-512 intrinsics (_mm512_min_ps, _mm512_cvtps_epi32, ...) start from a
  # self-initialized _mm512_undefined_*() value, which -Wuninitialized reports once inlined (GCC
  # bug 105593, fixed in GCC 13).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    list(APPEND EDGEWISE_ISA_FLAGS_avx512 -Wno-uninitialized -Wno-maybe-uninitialized)
  endif()
  set(EDGEWISE_ISAS_OF_OTHER_PROCESSORS neon)  # valid names this build must refuse
elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64)$")
  set(EDGEWISE_ISAS neon)
  set(EDGEWISE_ISA_FLAGS_neon "")  # Advanced SIMD is part of the AArch64 base
  set(EDGEWISE_ISAS_OF_OTHER_PROCESSORS sse2 sse4_1 avx2 avx512)
else()
  message(FATAL_ERROR "edgewise: unsupported processor ${CMAKE_SYSTEM_PROCESSOR}")
endif()

# EDGEWISE_ONLY_ISAS: a subset of EDGEWISE_ISAS to compile (empty: all of them). An ISA left out
# is refused like another processor's. For builds that check the kernels' code for something
# other than their results, such as the sanitizer builds: an ISA of the same vector width is the
# same kernel source again, and one this CPU lacks is never run.
set(EDGEWISE_ONLY_ISAS "" CACHE STRING
    "The ISAs to compile the kernels for, a subset of ${EDGEWISE_ISAS} (empty: all)")
if(EDGEWISE_ONLY_ISAS)
  string(REPLACE "," ";" _only_isas "${EDGEWISE_ONLY_ISAS}")
  foreach(isa IN LISTS _only_isas)
    if(NOT isa IN_LIST EDGEWISE_ISAS)
      message(FATAL_ERROR "edgewise: EDGEWISE_ONLY_ISAS names '${isa}', which is not one of "
                          "this processor's ISAs (${EDGEWISE_ISAS})")
    endif()
  endforeach()
  set(_kept_isas "")
  foreach(isa IN LISTS EDGEWISE_ISAS)
    if(isa IN_LIST _only_isas)
      list(APPEND _kept_isas ${isa})
    else()
      list(APPEND EDGEWISE_ISAS_OF_OTHER_PROCESSORS ${isa})
      # kernels/core/isa_list.hpp drops the ISA from the code's list.
      add_compile_definitions(EDGEWISE_LEAVE_OUT_${isa})
    endif()
  endforeach()
  set(EDGEWISE_ISAS ${_kept_isas})
  message(STATUS "edgewise: kernels compiled for ${EDGEWISE_ISAS} only (EDGEWISE_ONLY_ISAS)")
endif()

# Kernels give the same results on every ISA only without silent FMA contraction.
set(EDGEWISE_KERNEL_FLAGS -ffp-contract=off)

# edgewise_add_isa_objects(PREFIX SOURCES file... [INCLUDES dir...] [FLAGS flag...])
# Compiles the same sources once per ISA of EDGEWISE_ISAS, each into an OBJECT library
# PREFIX_<isa> with that ISA's flags and EDGEWISE_BUILD_ISA=<isa> (kernels/core/isa_build.hpp
# turns it into the ISA's namespace and xsimd architecture). Sets PREFIX_OBJECT_LIBRARIES in the
# caller's scope to the libraries made.
function(edgewise_add_isa_objects prefix)
  cmake_parse_arguments(ARG "" "" "SOURCES;INCLUDES;FLAGS" ${ARGN})
  set(libraries "")
  foreach(isa IN LISTS EDGEWISE_ISAS)
    set(target ${prefix}_${isa})
    add_library(${target} OBJECT ${ARG_SOURCES})
    target_compile_definitions(${target} PRIVATE EDGEWISE_BUILD_ISA=${isa})
    target_compile_options(${target} PRIVATE ${EDGEWISE_KERNEL_FLAGS} ${ARG_FLAGS}
                                             ${EDGEWISE_ISA_FLAGS_${isa}})
    target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/kernels
                                                 ${PROJECT_SOURCE_DIR}/kernels/include
                                                 ${ARG_INCLUDES})
    target_link_libraries(${target} PRIVATE xsimd)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    list(APPEND libraries ${target})
  endforeach()
  set(${prefix}_OBJECT_LIBRARIES ${libraries} PARENT_SCOPE)
endfunction()

# edgewise_link_isa_objects(TARGET LIBRARIES...): adds the objects of each library to TARGET.
function(edgewise_link_isa_objects target)
  foreach(objects IN LISTS ARGN)
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:${objects}>)
  endforeach()
endfunction()
