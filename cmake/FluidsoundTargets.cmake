# fluidsound_warnings(<target>): the project's warning set for its own targets.
function(fluidsound_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()

# fluidsound_add_library(<name>): the library of one stage folder, fluidsound::<name>, from every
# .cpp in the current folder, with the repository root on its include path and the project's
# warnings. <name> is the folder's path with "/" as "_" (sim/fluid: sim_fluid).
function(fluidsound_add_library name)
  file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  add_library(fluidsound_${name} STATIC ${sources})
  add_library(fluidsound::${name} ALIAS fluidsound_${name})
  target_include_directories(fluidsound_${name} PUBLIC "${PROJECT_SOURCE_DIR}")
  fluidsound_warnings(fluidsound_${name})
endfunction()
