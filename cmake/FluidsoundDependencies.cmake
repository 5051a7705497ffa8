# Every third-party package fluidsound builds against; all are Debian 12 packages installed by
# tools/setup.sh. Imported targets are SYSTEM includes, so -Wall -Wextra stays about our code.
find_package(TBB 2021 CONFIG REQUIRED)                 # parallel loops
find_package(embree 3 CONFIG REQUIRED)                 # ray queries against thin mesh walls
find_package(Eigen3 3.4 CONFIG REQUIRED)               # linear algebra, FFT (unsupported/Eigen/FFT)
find_package(nlohmann_json 3.11 CONFIG REQUIRED)       # scene and bubble-track files
find_package(tinyobjloader CONFIG REQUIRED)            # OBJ meshes (version "2rc10": no version test)
find_package(CLI11 CONFIG REQUIRED)                    # command line
find_package(spectra 1.0 CONFIG REQUIRED)              # water modes: shift-invert Lanczos (MPL-2.0)
find_package(GTest CONFIG REQUIRED)                    # tests
find_package(benchmark CONFIG REQUIRED)                # benchmarks
find_package(PkgConfig REQUIRED)
pkg_check_modules(SndFile REQUIRED IMPORTED_TARGET sndfile)   # WAV / FLAC
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)       # spectrogram PNG with labelled axes
pkg_check_modules(EBUR128 REQUIRED IMPORTED_TARGET libebur128)  # BS.1770 loudness, true peak
pkg_check_modules(MYSOFA REQUIRED IMPORTED_TARGET libmysofa)    # SOFA HRTF sets (binaural heads)
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)  # rigid bodies (zlib), doubles
# OpenVDB ships only a Find module, in a folder that also holds its own FindTBB: look for TBB
# (above) first, so oneTBB's config wins (toolchain facts, pitfall 1).
list(APPEND CMAKE_MODULE_PATH "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB")
find_package(OpenVDB 10 REQUIRED)                      # sparse level sets, .vdb files
