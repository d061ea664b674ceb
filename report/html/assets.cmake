# The HTML report's page (report/html/page.{html,css,js}) and the three.js bundle made by
# tools/html/setup.sh, embedded into mc_report as strings at build time (report/html_assets.hpp),
# so that `morphcut-city` writes a self-contained page without any file beside the binary.
# Without the bundle (no npm when configuring) the page is written without its 3D view.
set(MC_THREE_BUNDLE "${CMAKE_SOURCE_DIR}/build/node_tools/html/three-bundle.js" CACHE FILEPATH
    "three.js bundle for the HTML report's 3D view (tools/html/setup.sh makes it)")
set(_mc_html_dir ${CMAKE_SOURCE_DIR}/report/html)
set(_mc_html_three "")
if(MC_THREE_BUNDLE AND EXISTS "${MC_THREE_BUNDLE}")
  set(_mc_html_three "${MC_THREE_BUNDLE}")
else()
  message(STATUS "HTML report: no three.js bundle at ${MC_THREE_BUNDLE} (run tools/html/setup.sh): pages get no 3D view")
endif()
set(_mc_html_out ${CMAKE_BINARY_DIR}/generated/html_assets.cpp)
add_custom_command(
  OUTPUT ${_mc_html_out}
  COMMAND ${CMAKE_COMMAND} -DOUT=${_mc_html_out} -DDIR=${_mc_html_dir} -DTHREE=${_mc_html_three}
          -P ${_mc_html_dir}/embed.cmake
  DEPENDS ${_mc_html_dir}/embed.cmake ${_mc_html_dir}/page.html ${_mc_html_dir}/page.css
          ${_mc_html_dir}/page.js ${_mc_html_three}
  COMMENT "Embedding the HTML report's page and three.js"
  VERBATIM)
target_sources(mc_report PRIVATE ${_mc_html_out})
