# fluidsound_warnings(<target>): the project's warning set for its own targets.
function(fluidsound_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
