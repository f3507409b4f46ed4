#!/usr/bin/env bash
# Configures and builds the AddressSanitizer + UBSan build (build-asan/, clang) of the targets
# named: scripts/test.sh builds the test binary, the command line and the preset fuzzer there,
# scripts/fuzz.sh the fuzzer alone. Usage: scripts/sanitize-build.sh TARGET...
#
# clang, not GCC: on the 2-core machine, alone, clang compiled the test binary and the command
# line in 166-175 s where GCC took 252 s (336 s inside CI's run; its tests then ran in 171 s
# under clang, 123 s under GCC), and libFuzzer is clang's, so the fuzzer is one more target of the
# same build (all three: 240 s). core compiles at -O1, the app and the tests at -O0 (the top
# CMakeLists.txt); the test files that make a GL context are left out (tests/CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
# A build-asan/ configured with another compiler (GCC, before) is made again: CMake keeps the
# compiler it first found.
if [ -f build-asan/CMakeCache.txt ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' build-asan/CMakeCache.txt; then
  rm -rf build-asan
fi
launcher=(); command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-asan -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DFRAKTAL_SANITIZE=ON -DFRAKTAL_BUILD_EDITOR=OFF \
  -DFRAKTAL_TESTS_WITHOUT_GL=ON "${launcher[@]}" >/dev/null
targets=(); for t in "$@"; do targets+=(--target "$t"); done
cmake --build build-asan --parallel "$(nproc)" "${targets[@]}"
