# ONNX Runtime as the imported target onnxruntime::onnxruntime, from the directory scripts/fetch-onnxruntime.sh
# fills (library from PyPI's onnxruntime wheel, headers from Debian trixie's libonnxruntime-dev; see the README).
set(OCTOCAP_ONNXRUNTIME_DIR "${PROJECT_SOURCE_DIR}/.cache/onnxruntime" CACHE PATH
    "ONNX Runtime with include/ and lib/ (scripts/fetch-onnxruntime.sh)")
find_path(ONNXRUNTIME_INCLUDE_DIR onnxruntime_cxx_api.h
          HINTS "${OCTOCAP_ONNXRUNTIME_DIR}/include" PATH_SUFFIXES onnxruntime)
find_library(ONNXRUNTIME_LIBRARY NAMES onnxruntime libonnxruntime.so.1 HINTS "${OCTOCAP_ONNXRUNTIME_DIR}/lib")
if(NOT ONNXRUNTIME_INCLUDE_DIR OR NOT ONNXRUNTIME_LIBRARY)
  message(FATAL_ERROR "ONNX Runtime not found in ${OCTOCAP_ONNXRUNTIME_DIR}: run scripts/fetch-onnxruntime.sh "
                      "(or configure with -DOCTOCAP_WITH_ONNX=OFF to build without 2D detection)")
endif()
get_filename_component(ONNXRUNTIME_LIBRARY "${ONNXRUNTIME_LIBRARY}" REALPATH)
# Another runtime fetched into the directory (a new version, the GPU build of scripts/install-deps.sh --gpu) moves the
# soname link: configure again, so that the build links and installs the library that is there now.
if(EXISTS "${OCTOCAP_ONNXRUNTIME_DIR}/lib/libonnxruntime.so.1")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${OCTOCAP_ONNXRUNTIME_DIR}/lib/libonnxruntime.so.1")
endif()
add_library(onnxruntime::onnxruntime SHARED IMPORTED)
set_target_properties(onnxruntime::onnxruntime PROPERTIES
  IMPORTED_LOCATION "${ONNXRUNTIME_LIBRARY}"
  IMPORTED_SONAME "libonnxruntime.so.1"
  INTERFACE_INCLUDE_DIRECTORIES "${ONNXRUNTIME_INCLUDE_DIR}")
message(STATUS "ONNX Runtime: ${ONNXRUNTIME_LIBRARY}")
