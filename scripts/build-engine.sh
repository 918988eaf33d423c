#!/usr/bin/env bash
# Builds the Release engine: Simbody from Debian's own source package (the
# version of libsimbody-dev this machine's apt offers), CMake Release,
# libraries only, installed under a prefix outside the checkout:
#   ${MILLDYN_ENGINE_ROOT:-/opt/milldyn-engine}/simbody-<version>-<flags hash>
# Reused when present (a stamp records version and flags); rebuilt only when
# they change. Prints the prefix as its last line of output on stdout.
#
# The deb-src entry is derived from the machine's own apt sources into a
# private, temporary apt configuration (the machine's apt configuration is
# left untouched; no host name is written into any file of this checkout).
# Works as root with no stdin (CI=true) on a fresh Debian 12 machine; see
# docs/building.md.
set -euo pipefail

root="${MILLDYN_ENGINE_ROOT:-/opt/milldyn-engine}"
pkg=simbody

# Version: the source version of the libsimbody-dev apt would install, so the
# engine and the Debian fallback are the same Simbody.
version="$(apt-cache policy libsimbody-dev 2>/dev/null | awk '/Candidate:/ {print $2}')"
if [ -z "$version" ] || [ "$version" = "(none)" ]; then  # no package lists: the installed one
  version="$(dpkg-query -W -f='${Version}' libsimbody-dev 2>/dev/null || true)"
fi
if [ -z "$version" ] || [ "$version" = "(none)" ]; then
  echo "build-engine: apt knows no libsimbody-dev version (run apt-get update)" >&2
  exit 1
fi

# Flags: everything that changes the built library. The hash names the prefix.
cmake_flags=(
  -DCMAKE_BUILD_TYPE=Release
  -DBUILD_EXAMPLES=OFF
  -DBUILD_TESTING=OFF
  -DBUILD_VISUALIZER=OFF
  -DBUILD_STATIC_LIBRARIES=OFF
  -DINSTALL_DOCS=OFF
  -DCMAKE_INSTALL_LIBDIR=lib
  -DSIMBODY_VISUALIZER_INSTALL_DIR=libexec/simbody   # required by Debian patch 0001
)
# Optional build-time patches (scripts/engine-patches/NAME.patch, applied
# with patch -p1), chosen by name: MILLDYN_ENGINE_PATCHES="NAME ...". None by
# default; their contents are part of the flags, so a patched engine has a
# prefix of its own (docs/building.md, "Engine patches").
patch_dir="$(cd "$(dirname "$0")" && pwd)/engine-patches"
patches=()
for name in ${MILLDYN_ENGINE_PATCHES:-}; do
  [ -f "$patch_dir/$name.patch" ] || { echo "build-engine: no patch $patch_dir/$name.patch" >&2; exit 1; }
  patches+=("$patch_dir/$name.patch")
done
patch_id=""
for p in "${patches[@]}"; do patch_id+="patch $(basename "$p") $(sha256sum < "$p" | cut -c1-16)"$'\n'; done
flags_id="$(printf '%s\n' "${cmake_flags[@]}" "$(g++ -dumpfullversion 2>/dev/null || echo nogxx)")${patch_id:+$'\n'}${patch_id%$'\n'}"
hash="$(printf '%s' "$flags_id" | sha256sum | cut -c1-10)"
safe_version="${version//[:+~]/_}"
prefix="$root/$pkg-$safe_version-$hash"
stamp="$prefix/.milldyn-engine-stamp"
stamp_text="$(printf 'simbody %s\n%s\n' "$version" "$flags_id")"

# simbody-current: the last engine built or reused, the default of
# MILLDYN_ENGINE_PREFIX for a cmake run by hand (cmake/Engine.cmake).
point_current() {
  "${sudo_cmd[@]}" ln -sfn "$(basename "$prefix")" "$root/simbody-current"
}
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "build-engine: need root or sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$stamp_text" ]; then
  echo "build-engine: reusing $prefix" >&2
  [ "$(readlink "$root/simbody-current" 2>/dev/null)" = "$(basename "$prefix")" ] || point_current
  echo "$prefix"
  exit 0
fi

# Build dependencies of the libraries (no visualizer: no OpenGL/GLUT).
deps=(cmake g++ ninja-build dpkg-dev patch liblapack-dev libblas-dev)
missing=()
for p in "${deps[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build-engine: installing ${missing[*]}" >&2
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/milldyn-engine.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# A private apt configuration whose only entries are deb-src twins of the
# machine's enabled "deb" entries (deb822 *.sources and one-line *.list).
mkdir -p "$work/apt/sources.list.d" "$work/apt/lists/partial" "$work/apt/cache/archives/partial"
: > "$work/apt/sources.list"
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] || continue
  sed -n -E 's/^[[:space:]]*deb([[:space:]])/deb-src\1/p' "$f" >> "$work/apt/sources.list"
done
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  # Each stanza: keep those whose Types include "deb", and make them deb-src.
  awk 'BEGIN { RS = ""; ORS = "\n\n" }
       {
         n = split($0, line, "\n"); keep = 0; out = ""
         for (i = 1; i <= n; i++) {
           if (line[i] ~ /^#/) continue
           if (line[i] ~ /^Types:/) {
             if (line[i] ~ /[[:space:]]deb([[:space:]]|$)/) keep = 1
             line[i] = "Types: deb-src"
           }
           if (line[i] ~ /^Enabled:[[:space:]]*no/) keep = 0
           out = out line[i] "\n"
         }
         if (keep) print out
       }' "$f" > "$work/apt/sources.list.d/$(basename "$f")"
done
apt_opts=(
  -o Dir::Etc::SourceList="$work/apt/sources.list"
  -o Dir::Etc::SourceParts="$work/apt/sources.list.d"
  -o Dir::State::Lists="$work/apt/lists"
  -o Dir::Cache="$work/apt/cache"
  -o Debug::NoLocking=1
  -o APT::Sandbox::User="$(id -un)"
)
echo "build-engine: fetching the source of simbody $version" >&2
# A third-party entry without sources must not stop us: the source fetch
# below is the check that matters.
apt-get "${apt_opts[@]}" update -qq >&2 || echo "build-engine: some deb-src entries failed to update" >&2
(cd "$work" && apt-get "${apt_opts[@]}" source -qq "$pkg=$version" >&2)
src="$(find "$work" -mindepth 1 -maxdepth 1 -type d -name "$pkg-*" | head -n1)"
[ -n "$src" ] && [ -f "$src/CMakeLists.txt" ] || { echo "build-engine: no unpacked simbody source in $work" >&2; exit 1; }

for p in "${patches[@]}"; do
  echo "build-engine: applying $(basename "$p")" >&2
  patch -d "$src" -p1 --forward --batch < "$p" >&2
done

jobs="${MILLDYN_ENGINE_JOBS:-$(nproc)}"
echo "build-engine: building simbody $version (Release, libraries only, -j$jobs) into $prefix" >&2
cmake -S "$src" -B "$work/build" -G Ninja -DCMAKE_INSTALL_PREFIX="$prefix" "${cmake_flags[@]}" >&2
nice cmake --build "$work/build" -j"$jobs" >&2
"${sudo_cmd[@]}" rm -rf "$prefix"
"${sudo_cmd[@]}" cmake --install "$work/build" >&2
printf '%s' "$stamp_text" | "${sudo_cmd[@]}" tee "$stamp" >/dev/null
point_current
echo "build-engine: installed $prefix" >&2
echo "$prefix"
