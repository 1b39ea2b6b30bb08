# The stages of DESIGN.md as libraries. octocap_stage(NAME SOURCES ... [STAGES earlier ...] [PUBLIC libs ...]
# [PRIVATE libs ... [OPENCV]]) makes octocap_stage_NAME, a static library (PIC, hidden symbols: liboctocap.so exports
# the C ABI alone) that links the earlier stages it names and its own third-party libraries. OPENCV in PRIVATE puts
# OpenCV's headers on the include path of the stage and of the stages built on it, whose headers may hold cv::Mat
# (Debian's per-module packages ship no CMake config).

function(octocap_stage stage)
  cmake_parse_arguments(S "" "" "SOURCES;STAGES;PUBLIC;PRIVATE" ${ARGN})
  set(target octocap_stage_${stage})
  add_library(${target} STATIC ${S_SOURCES})
  foreach(dep ${S_STAGES})
    if(NOT TARGET octocap_stage_${dep})
      message(FATAL_ERROR "stage ${stage} names ${dep}, which is not an earlier stage")
    endif()
    target_link_libraries(${target} PUBLIC octocap_stage_${dep})
  endforeach()
  set(private_libs ${S_PRIVATE})
  set(precompiled <Eigen/Dense> <Eigen/Geometry>)
  if("OPENCV" IN_LIST private_libs)
    list(REMOVE_ITEM private_libs OPENCV)
    target_include_directories(${target} SYSTEM PUBLIC ${OPENCV_INCLUDE_DIR})
    list(APPEND precompiled <opencv2/core.hpp>)
  endif()
  target_link_libraries(${target} PUBLIC ${S_PUBLIC} PRIVATE ${private_libs})
  # The internal include path is private: only octocap_internals (tests, benchmarks, the sample generator) exposes it.
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src
                                       PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  # Hidden, C too: the IDL's generated type descriptors (octocap_wire_*) are not part of the ABI.
  set_target_properties(${target} PROPERTIES CXX_VISIBILITY_PRESET hidden C_VISIBILITY_PRESET hidden
                                             VISIBILITY_INLINES_HIDDEN ON)
  octocap_warnings(${target})
  octocap_precompile(${target} ${precompiled})
  octocap_unity(${target})
  set_property(GLOBAL APPEND PROPERTY OCTOCAP_STAGES ${stage})
endfunction()

# A static library links whatever it leaves undefined only when a program links it, so a stage calling a later
# one would still build. Each stage is therefore also linked on its own into a shared object with --no-undefined:
# every symbol it uses must come from itself, the stages it names or its libraries, or the build fails. The
# sanitizer builds skip it (a shared object there leaves the sanitizer runtime's symbols to the program); the normal
# build, which CI runs first, holds the line.
function(octocap_stage_checks)
  if(OCTOCAP_SANITIZE OR OCTOCAP_FUZZ)
    return()
  endif()
  set(empty ${CMAKE_CURRENT_BINARY_DIR}/stage_check.cpp)
  # Written only when it changes, so that configuring again relinks nothing.
  file(CONFIGURE OUTPUT ${empty} CONTENT "// the stage's objects are the library: see cmake/Stages.cmake\n")
  get_property(stages GLOBAL PROPERTY OCTOCAP_STAGES)
  foreach(stage ${stages})
    add_library(octocap_check_${stage} SHARED ${empty})
    target_link_libraries(octocap_check_${stage} PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,octocap_stage_${stage}>")
    target_link_options(octocap_check_${stage} PRIVATE -Wl,--no-undefined)
  endforeach()
endfunction()
