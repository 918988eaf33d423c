#!/usr/bin/env bash
# Builds the libFuzzer targets with ASan+UBSan (clang) and runs each for the
# given number of seconds (default 60), seeded with models/ and the bad-input
# test files. Findings land in build-fuzz/findings/; a finding fails the run.
#   scripts/fuzz.sh 1800      # 30 minutes per target
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
scripts/install-deps.sh
command -v clang++ >/dev/null || { DEBIAN_FRONTEND=noninteractive apt-get install -y -qq clang libclang-rt-14-dev; }
# fuzzer-no-link instruments every library for coverage; only the targets link libFuzzer.
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
  -DMILLDYN_FUZZ=ON -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target model_reader_fuzz units_fuzz
mkdir -p build-fuzz/corpus/model build-fuzz/corpus/units build-fuzz/findings
cp models/*.yaml tests/testdata/*.yaml tests/testdata/bad/*.yaml build-fuzz/corpus/model/ 2>/dev/null || true
printf '%s\n' "1446 rpm" "190.7e-4 kg*m^2" "537 N*m/rad" "40 deg" "130 kg/h" "6.428 N*m*s/rad" \
  "(m/s)^2" "1/s" > build-fuzz/corpus/units/seeds.txt
for target in model_reader_fuzz units_fuzz; do
  corpus=build-fuzz/corpus/${target%%_fuzz}
  [ "$target" = units_fuzz ] && corpus=build-fuzz/corpus/units
  [ "$target" = model_reader_fuzz ] && corpus=build-fuzz/corpus/model
  echo "fuzz: $target for ${seconds} s"
  build-fuzz/$target "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -artifact_prefix=build-fuzz/findings/ -print_final_stats=1 2>&1 | tail -n 12
done
