# The inspector's page (web/inspector, docs/inspector.md), laid out in the build folder where the
# programs that serve it find it: its own files, and the layout engine ELK (elkjs, from the npm
# registry: `scripts/run deps` installs it into web/node_modules) bundled beside them, so that
# the page works offline. Without elkjs the page says so, and the browser tests report skipped.
set(BSC_INSPECTOR_WEB_ROOT ${PROJECT_BINARY_DIR}/web/inspector)
set(BSC_INSPECTOR_ELK ${PROJECT_SOURCE_DIR}/web/node_modules/elkjs/lib/elk.bundled.js)
file(GLOB bsc_inspector_sources CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/web/inspector/*.html
  ${PROJECT_SOURCE_DIR}/web/inspector/*.js
  ${PROJECT_SOURCE_DIR}/web/inspector/*.css)
set(bsc_inspector_outputs)
foreach(source IN LISTS bsc_inspector_sources)
  get_filename_component(name ${source} NAME)
  add_custom_command(OUTPUT ${BSC_INSPECTOR_WEB_ROOT}/${name}
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${source} ${BSC_INSPECTOR_WEB_ROOT}/${name}
    DEPENDS ${source} VERBATIM)
  list(APPEND bsc_inspector_outputs ${BSC_INSPECTOR_WEB_ROOT}/${name})
endforeach()
if(EXISTS ${BSC_INSPECTOR_ELK})
  add_custom_command(OUTPUT ${BSC_INSPECTOR_WEB_ROOT}/elk.bundled.js
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${BSC_INSPECTOR_ELK} ${BSC_INSPECTOR_WEB_ROOT}/elk.bundled.js
    DEPENDS ${BSC_INSPECTOR_ELK} VERBATIM)
  list(APPEND bsc_inspector_outputs ${BSC_INSPECTOR_WEB_ROOT}/elk.bundled.js)
else()
  message(STATUS "bsc: web/node_modules/elkjs not found (scripts/run deps installs it): "
    "the inspector page cannot lay out charts, and its browser tests report skipped")
endif()
add_custom_target(bsc_inspector_web ALL DEPENDS ${bsc_inspector_outputs})
