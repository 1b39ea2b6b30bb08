# OpenVINO's C API as the imported target openvino::c, from the directory scripts/fetch-openvino.sh fills (PyPI's
# openvino wheel: the runtime, its C API and headers, the CPU plugin, the ONNX reader, oneTBB).
set(OCTOCAP_OPENVINO_DIR "${PROJECT_SOURCE_DIR}/.cache/openvino" CACHE PATH
    "OpenVINO with include/ and lib/ (scripts/fetch-openvino.sh)")
find_path(OPENVINO_INCLUDE_DIR openvino/c/openvino.h HINTS "${OCTOCAP_OPENVINO_DIR}/include")
find_library(OPENVINO_C_LIBRARY NAMES openvino_c libopenvino_c.so.2640 HINTS "${OCTOCAP_OPENVINO_DIR}/lib" NO_DEFAULT_PATH)
if(NOT OPENVINO_INCLUDE_DIR OR NOT OPENVINO_C_LIBRARY)
  message(FATAL_ERROR "OpenVINO not found in ${OCTOCAP_OPENVINO_DIR}: run scripts/fetch-openvino.sh "
                      "(or configure with -DOCTOCAP_WITH_OPENVINO=OFF: ONNX Runtime alone)")
endif()
get_filename_component(OPENVINO_C_LIBRARY "${OPENVINO_C_LIBRARY}" REALPATH)
get_filename_component(OPENVINO_LIB_DIR "${OPENVINO_C_LIBRARY}" DIRECTORY)
get_filename_component(OPENVINO_C_SONAME "${OPENVINO_C_LIBRARY}" NAME)
add_library(openvino::c SHARED IMPORTED)
set_target_properties(openvino::c PROPERTIES
  IMPORTED_LOCATION "${OPENVINO_C_LIBRARY}"
  IMPORTED_SONAME "${OPENVINO_C_SONAME}"
  INTERFACE_INCLUDE_DIRECTORIES "${OPENVINO_INCLUDE_DIR}")
message(STATUS "OpenVINO: ${OPENVINO_C_LIBRARY}")
