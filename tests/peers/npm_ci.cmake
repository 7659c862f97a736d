# Installs the test peers' npm dependencies (pinned by package-lock.json) into the build tree with
# `npm ci`, using npm's cache first; skipped when the installed lock file is the same.
# -DSRC=<tests/peers> -DDST=<build dir> -DNPM=<npm>
file(MAKE_DIRECTORY ${DST})
foreach(f package.json package-lock.json sim_vehicle.mjs)
  configure_file(${SRC}/${f} ${DST}/${f} COPYONLY)
endforeach()
if(EXISTS ${DST}/node_modules/.package-lock.json AND EXISTS ${DST}/installed-lock.json)
  file(SHA256 ${DST}/package-lock.json want)
  file(SHA256 ${DST}/installed-lock.json have)
  if(want STREQUAL have)
    message(STATUS "test peers: npm dependencies already installed")
    return()
  endif()
endif()
execute_process(COMMAND ${NPM} ci --prefer-offline --no-audit --no-fund
                WORKING_DIRECTORY ${DST} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "test peers: npm ci failed (${rc}); the npm registry or its cache is needed once")
endif()
configure_file(${DST}/package-lock.json ${DST}/installed-lock.json COPYONLY)
