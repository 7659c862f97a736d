# The documentation pages (docs/*.md) rendered to HTML at build time with pandoc, for the
# application's Help > User guide (compiled into pf_ui as Qt resources under :/help/) and for the
# package (/usr/share/doc/photoflight/html). One Markdown source serves GitHub, the program and the
# package. Included from ui/CMakeLists.txt so that the HTML and the resource file that holds it are
# built in one directory.
set(PF_DOC_DIR_SRC "${PROJECT_SOURCE_DIR}/docs")
# Every page, in the order of the guide's contents.
set(PF_DOC_PAGES
  index.md
)
# Pictures the pages show (docs/images/), copied beside the HTML.
file(GLOB PF_DOC_IMAGES RELATIVE "${PF_DOC_DIR_SRC}" CONFIGURE_DEPENDS "${PF_DOC_DIR_SRC}/images/*.png")

find_program(PF_PANDOC pandoc)
if(NOT PF_PANDOC)
  message(FATAL_ERROR "pandoc not found: it renders the user guide (packaging/install-deps.sh installs it)")
endif()

set(PF_DOC_HTML_DIR "${CMAKE_CURRENT_BINARY_DIR}/help")
set(PF_DOC_OUTPUTS)
foreach(page IN LISTS PF_DOC_PAGES)
  string(REGEX REPLACE "\\.md$" ".html" html "${page}")
  add_custom_command(
    OUTPUT "${PF_DOC_HTML_DIR}/${html}"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${PF_DOC_HTML_DIR}"
    COMMAND ${PF_PANDOC} --from=gfm --to=html5 --standalone
            --lua-filter=${PF_DOC_DIR_SRC}/tools/help_links.lua
            --template=${PF_DOC_DIR_SRC}/tools/help_template.html
            --output=${PF_DOC_HTML_DIR}/${html} ${PF_DOC_DIR_SRC}/${page}
    DEPENDS "${PF_DOC_DIR_SRC}/${page}" "${PF_DOC_DIR_SRC}/tools/help_links.lua"
            "${PF_DOC_DIR_SRC}/tools/help_template.html"
    COMMENT "Rendering the user guide page ${page}"
    VERBATIM)
  list(APPEND PF_DOC_OUTPUTS "${PF_DOC_HTML_DIR}/${html}")
endforeach()
foreach(image IN LISTS PF_DOC_IMAGES)
  add_custom_command(
    OUTPUT "${PF_DOC_HTML_DIR}/${image}"
    COMMAND ${CMAKE_COMMAND} -E copy "${PF_DOC_DIR_SRC}/${image}" "${PF_DOC_HTML_DIR}/${image}"
    DEPENDS "${PF_DOC_DIR_SRC}/${image}"
    VERBATIM)
  list(APPEND PF_DOC_OUTPUTS "${PF_DOC_HTML_DIR}/${image}")
endforeach()

# The resource file naming every rendered file, written at configure time (the list is known then).
set(PF_DOC_QRC "${CMAKE_CURRENT_BINARY_DIR}/help.qrc")
set(qrc "<RCC>\n  <qresource prefix=\"/help\">\n")
foreach(out IN LISTS PF_DOC_OUTPUTS)
  file(RELATIVE_PATH rel "${PF_DOC_HTML_DIR}" "${out}")
  string(APPEND qrc "    <file alias=\"${rel}\">${out}</file>\n")
endforeach()
string(APPEND qrc "  </qresource>\n</RCC>\n")
file(CONFIGURE OUTPUT "${PF_DOC_QRC}" CONTENT "${qrc}")
add_custom_target(pf_docs_html DEPENDS ${PF_DOC_OUTPUTS})
# The same pages in the package, for a browser and for the manual pages' SEE ALSO.
install(DIRECTORY "${PF_DOC_HTML_DIR}/" DESTINATION "${CMAKE_INSTALL_DATADIR}/doc/photoflight/html")
