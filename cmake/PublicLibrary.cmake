# rasterliquids_public_library(TARGET NAME): makes the static library TARGET one of the package's,
# RasterLiquids::NAME: the alias, its export name, the public headers (the source tree's include/,
# installed under include/rasterliquids/) and, privately, the source root for its internal headers.
function(rasterliquids_public_library target name)
  add_library(RasterLiquids::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
                                              $<INSTALL_INTERFACE:${RASTERLIQUIDS_INCLUDE_DIR}>
                                       PRIVATE ${PROJECT_SOURCE_DIR})
endfunction()
