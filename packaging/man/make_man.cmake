# Writes a gzipped manual page from a program's own --help with help2man (run as `cmake -P`), so the
# page says exactly what the program says. Variables:
#   PROGRAM   the built executable           NAME     the one-line description for NAME
#   INCLUDE   a help2man include file         OUTPUT   the .1.gz to write
#   SUBCOMMANDS  ON for a program with commands: the commands listed under "Commands:" in its
#             --help are read from there, and each one's `PROGRAM CMD --help` becomes a part of a
#             COMMANDS section, verbatim, so every command's options are in the page too and a new
#             command needs no change here.
#   HELP2MAN  the help2man executable
# QT_QPA_PLATFORM=offscreen lets the desktop program answer --help without a display.
set(ENV{QT_QPA_PLATFORM} offscreen)
get_filename_component(out_dir "${OUTPUT}" DIRECTORY)
get_filename_component(out_name "${OUTPUT}" NAME_WE)
set(work "${out_dir}/${out_name}")
file(MAKE_DIRECTORY "${out_dir}")
file(READ "${INCLUDE}" include_text)

set(COMMANDS "")
if(SUBCOMMANDS)
  execute_process(COMMAND "${PROGRAM}" --help OUTPUT_VARIABLE top_help RESULT_VARIABLE rc)
  string(REGEX MATCH "Commands:\n(  [a-z]+[^\n]*\n)+" listed "${top_help}")
  string(REGEX MATCHALL "\n  [a-z]+" names "${listed}")
  foreach(n IN LISTS names)
    string(STRIP "${n}" n)
    list(APPEND COMMANDS "${n}")
  endforeach()
  if(NOT COMMANDS)
    message(FATAL_ERROR "${PROGRAM} --help lists no commands under 'Commands:'")
  endif()
  string(APPEND include_text "\n[COMMANDS]\n")
  foreach(cmd IN LISTS COMMANDS)
    execute_process(COMMAND "${PROGRAM}" ${cmd} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${PROGRAM} ${cmd} --help failed (${rc})")
    endif()
    # roff: a backslash is written \e, and a line starting with . or ' is protected by \&.
    string(REPLACE "\\" "\\e" help "${help}")
    string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
    string(APPEND include_text ".SS \"${cmd}\"\n.nf\n${help}.fi\n")
  endforeach()
endif()
file(WRITE "${work}.h2m" "${include_text}")

execute_process(
  COMMAND "${HELP2MAN}" --no-info --no-discard-stderr --name "${NAME}" --include "${work}.h2m"
          --output "${work}.1" "${PROGRAM}"
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man failed for ${PROGRAM} (${rc})")
endif()
# Debian's policy: manual pages compressed with gzip -9n (no name or time stamp inside).
execute_process(COMMAND gzip -9nf "${work}.1" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip failed for ${work}.1")
endif()
