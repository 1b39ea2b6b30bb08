# Build speed. Precompiled headers for the targets with many translation units: the third-party headers nearly
# every one of their files includes (Eigen, OpenCV's core, the standard library; Catch2 for the tests) are parsed
# once per target instead of once per file. Parsing them costs ~3.5 s a file here, a third of the build on two
# cores. Only third-party and standard headers go in: octocap's own headers differ per file (the tests include
# either the public octocap.hpp or internals, which must not meet), and a file must still compile without the
# precompiled header (OCTOCAP_PCH=OFF).
option(OCTOCAP_PCH "Precompiled headers for the large targets (faster builds)" ON)

# octocap_precompile(TARGET [HEADER ...]): the standard headers, and the given ones (those on the target's include
# path: <Eigen/Dense>, <opencv2/core.hpp>, ...).
function(octocap_precompile target)
  if(NOT OCTOCAP_PCH)
    return()
  endif()
  set(headers <algorithm> <array> <cmath> <cstdint> <functional> <map> <memory> <mutex> <string> <thread> <vector>
              ${ARGN})
  set(cxx_headers)
  foreach(h ${headers})
    # C++ files only (a target may hold C files too); a header's closing '>' would end the expression: $<ANGLE-R>.
    string(REGEX REPLACE ">$" "$<ANGLE-R>" h "${h}")
    list(APPEND cxx_headers "$<$<COMPILE_LANGUAGE:CXX>:${h}>")
  endforeach()
  target_precompile_headers(${target} PRIVATE ${cxx_headers})
endfunction()

# Unity builds for the targets whose files share one world (the core, the C ABI, the command line): their files are
# compiled eight to a translation unit, so the headers and templates they share are compiled once per eight; the
# instrumented core built in 267 s of CPU instead of 443. The tests stay file by file (they mix the public C++ header
# with internals on purpose), and scripts/check-minimal.sh builds with OCTOCAP_UNITY=OFF, so that every file of the
# core still compiles on its own includes.
option(OCTOCAP_UNITY "Unity builds of the library and the command line (faster builds)" ON)

function(octocap_unity target)
  if(OCTOCAP_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
endfunction()
