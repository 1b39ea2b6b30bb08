# An installed program finds the installed liboctocap (and the ONNX Runtime beside it) through RUNPATH
# $ORIGIN/../lib: it runs from whatever prefix it was installed to, without LD_LIBRARY_PATH.
function(octocap_install_program target)
  file(RELATIVE_PATH to_lib "/p/${CMAKE_INSTALL_BINDIR}" "/p/${CMAKE_INSTALL_LIBDIR}")
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/${to_lib}")
  install(TARGETS ${target} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()
