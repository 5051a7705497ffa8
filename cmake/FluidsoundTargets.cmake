# fluidsound_warnings(<target>): the project's warning set for its own targets.
function(fluidsound_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()

# fluidsound_add_library(<folder>): the library of one stage folder, fluidsound::<folder>, from
# every .cpp in it, with the repository root on its include path and the project's warnings.
function(fluidsound_add_library folder)
  file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  add_library(fluidsound_${folder} STATIC ${sources})
  add_library(fluidsound::${folder} ALIAS fluidsound_${folder})
  target_include_directories(fluidsound_${folder} PUBLIC "${PROJECT_SOURCE_DIR}")
  fluidsound_warnings(fluidsound_${folder})
endfunction()
