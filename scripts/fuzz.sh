#!/usr/bin/env bash
# Builds the libFuzzer targets with ASan+UBSan (clang) and runs each for the
# given number of seconds (default 60). Findings land in build-fuzz/findings/;
# a finding fails the run (docs/reliability.md).
#   model_reader_fuzz  model text -> ModelSpec or SpecError
#   scene_build_fuzz   model text -> Simbody scene (what the reader accepts must build)
#   units_fuzz         unit expressions
# The model targets are seeded with every shipped model, part file and
# bad-input file, and get a dictionary of every key those files use.
#   scripts/fuzz.sh 1800      # 30 minutes per target
#   scripts/fuzz.sh 60 scene_build_fuzz
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(model_reader_fuzz scene_build_fuzz units_fuzz)
scripts/install-deps.sh
command -v clang++ >/dev/null || { DEBIAN_FRONTEND=noninteractive apt-get install -y -qq clang libclang-rt-14-dev; }
# fuzzer-no-link instruments every library for coverage; only the targets link libFuzzer.
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
  -DMILLDYN_FUZZ=ON -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"
mkdir -p build-fuzz/corpus/model build-fuzz/corpus/units build-fuzz/findings
find models tests/testdata -name '*.yaml' -exec cp {} build-fuzz/corpus/model/ \; 2>/dev/null || true
# Every key of the shipped files, and the unit words, as a libFuzzer dictionary.
{ grep -ohE '^[ -]*[a-z_][a-z0-9_]*:' $(find models tests/testdata -name '*.yaml') | sed -E 's/^[ -]*//' | sort -u
  printf '%s\n' "N*m" "kg*m^2" "rad/s" "rpm" "deg" "rad" "m" "mm" "s" "ms" "%" "&a " "*a" "<<: " "#set "
} | sed 's/\\/\\\\/g; s/"/\\"/g; s/.*/"&"/' > build-fuzz/model.dict
printf '%s\n' "1446 rpm" "190.7e-4 kg*m^2" "537 N*m/rad" "40 deg" "130 kg/h" "6.428 N*m*s/rad" \
  "(m/s)^2" "1/s" > build-fuzz/corpus/units/seeds.txt
status=0
for target in "${targets[@]}"; do
  corpus=build-fuzz/corpus/model
  dict=(-dict=build-fuzz/model.dict)
  [ "$target" = units_fuzz ] && { corpus=build-fuzz/corpus/units; dict=(); }
  echo "fuzz: $target for ${seconds} s"
  # The last lines: libFuzzer's DONE line (coverage edges, corpus) and its
  # final stats, or the report and the artifact of a finding (the
  # recommended-dictionary listing, which pushed the DONE line out, is left out).
  build-fuzz/$target "$corpus" "${dict[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -artifact_prefix=build-fuzz/findings/$target- -print_final_stats=1 2>&1 |
    grep -viE '# uses: [0-9]+$|recommended dictionary' | tail -n 12 || status=1
done
exit $status
