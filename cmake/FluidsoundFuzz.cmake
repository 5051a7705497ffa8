# FLUIDSOUND_FUZZ: the libFuzzer build (tests/fuzz/README.md), in a folder of its own (build-fuzz/,
# configured with CXX=clang++-14 and CMAKE_BUILD_TYPE=Fuzz). The stage libraries get AddressSanitizer,
# UndefinedBehaviorSanitizer (every report fatal, so libFuzzer sees it as a crash) and libFuzzer's
# coverage counters; the harnesses of tests/fuzz/ add libFuzzer's main (-fsanitize=fuzzer).
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "FLUIDSOUND_FUZZ needs clang (libFuzzer): configure a separate folder with "
                      "CXX=clang++-14, found ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER}")
endif()
# Build type Fuzz: optimised enough for useful executions per second, assertions kept, line tables
# for the sanitizers' stack traces.
set(CMAKE_CXX_FLAGS_FUZZ "-O1 -gline-tables-only" CACHE STRING "Flags of the Fuzz build type")
set(fluidsound_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
add_compile_options(${fluidsound_sanitizers} -fsanitize=fuzzer-no-link)
add_link_options(${fluidsound_sanitizers})
