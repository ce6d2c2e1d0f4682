# cmake -P: writes OUT (a header defining PRIDE_GIT_COMMIT, `git describe --always --dirty` of
# SOURCE, or "unknown" without git) only when its text changes, so that a build names the source
# it was built from and recompiles only when that changed. Run at every build by
# experiment/html/CMakeLists.txt (target pride_git_commit).
set(commit unknown)
if(GIT_EXECUTABLE AND EXISTS ${SOURCE}/.git)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --always --dirty WORKING_DIRECTORY ${SOURCE}
                  OUTPUT_VARIABLE described OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE status ERROR_QUIET)
  if(status EQUAL 0 AND NOT described STREQUAL "")
    set(commit ${described})
  endif()
endif()
set(text "// Made by cmake/git_commit.cmake at build time: do not edit.\n#define PRIDE_GIT_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
