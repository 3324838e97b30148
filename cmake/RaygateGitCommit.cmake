# The git commit raygate is built from, for `raygate --version` (issue 26: two builds could not
# be told apart). Read at configure time from the source tree with the local git, no network:
#   RAYGATE_GIT_COMMIT  "60ebc9f1a2b3", "60ebc9f1a2b3-dirty" (local changes when configured), or
#                       "unknown" outside a git checkout or without git.
# Configure runs again when HEAD or the branch it points at moves, so a new commit is seen
# without a fresh build folder; edits after configuring are not (the "-dirty" is configure's).
function(raygate_git_commit out_var)
  set(commit "unknown")
  find_package(Git QUIET)
  if(GIT_FOUND)
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${PROJECT_SOURCE_DIR}" rev-parse --short=12 HEAD
                    OUTPUT_VARIABLE head RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE
                    ERROR_QUIET)
    if(NOT failed AND head)
      set(commit "${head}")
      execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${PROJECT_SOURCE_DIR}" status --porcelain
                              --untracked-files=no
                      OUTPUT_VARIABLE changes ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      if(changes)
        string(APPEND commit "-dirty")
      endif()
      execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${PROJECT_SOURCE_DIR}" rev-parse
                              --path-format=absolute --git-path HEAD
                      OUTPUT_VARIABLE head_file ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${PROJECT_SOURCE_DIR}" symbolic-ref -q HEAD
                      OUTPUT_VARIABLE branch ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      set(watched "${head_file}")
      if(branch)
        execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${PROJECT_SOURCE_DIR}" rev-parse
                                --path-format=absolute --git-path "${branch}"
                        OUTPUT_VARIABLE ref_file ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
        list(APPEND watched "${ref_file}")
      endif()
      foreach(file IN LISTS watched)
        if(EXISTS "${file}")
          set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${file}")
        endif()
      endforeach()
    endif()
  endif()
  set(${out_var} "${commit}" PARENT_SCOPE)
endfunction()
