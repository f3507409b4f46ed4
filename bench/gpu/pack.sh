#!/usr/bin/env bash
# Packs the Release build for a lent GPU machine (../shared/GPU.md): into .gpu/ (git ignores it)
# the stripped fraktal binary, every shared library it needs beyond glibc, libstdc++ and the GL
# dispatch libraries, the presets and the OCIO config; into .gl/ the Debian packages of the GL
# dispatch libraries (glvnd), which the GPU machine unpacks over its own NVIDIA driver; for the
# editor's run, Xvfb and xdotool with the libraries they need; and .gpu/with-libs, which runs a
# carried program with the carried libraries.
# Usage: bench/gpu/pack.sh [BUILD_DIR]     (default build/; builds it first with scripts/build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build}"
cd "$root"
[ -x "$build/app/fraktal" ] || scripts/build.sh

rm -rf .gpu && mkdir -p .gpu/lib .gpu/bin .gpu/config
# What the GPU machine has (glibc, the C++ runtime) or must take from its driver (GL, EGL, GLX):
# never carried, so that the NVIDIA vendor libraries are the ones loaded.
skip='^(libc|libm|libpthread|libdl|librt|ld-linux.*|libstdc\+\+|libgcc_s|libEGL|libGL|libGLX|libGLdispatch|libOpenGL|libGLESv2|libvulkan)\.so'
carry_libs() {  # the libraries `ldd` resolves for each binary, less the ones above
  ldd "$@" | awk '/=> \//{print $3}' | sort -u | while read -r lib; do
    name=$(basename "$lib")
    [[ "$name" =~ $skip ]] && continue
    cp -L "$lib" .gpu/lib/
  done
}
strip -o .gpu/fraktal "$build/app/fraktal"
carry_libs "$build/app/fraktal"
cp -r presets .gpu/presets
cp -r config/ocio .gpu/config/ocio
# The editor's run: a virtual X server and xdotool (their own libraries come along; GLX on the
# NVIDIA driver is the GPU machine's).
for tool in Xvfb xdotool; do
  path=$(command -v "$tool" || true)
  [ -n "$path" ] || { echo "pack: $tool is not installed (scripts/install-deps.sh installs it)" >&2; exit 1; }
  cp -L "$path" .gpu/bin/
  carry_libs "$path"
done
# Xvfb's keyboard map compiler and data.
if [ -x /usr/bin/xkbcomp ]; then cp -L /usr/bin/xkbcomp .gpu/bin/; carry_libs /usr/bin/xkbcomp; fi
[ -d /usr/share/X11/xkb ] && cp -r /usr/share/X11/xkb .gpu/xkb

# The GL dispatch libraries as Debian packages (the GPU machine has no package manager's network).
mkdir -p .gl
if ! ls .gl/libegl1_*.deb >/dev/null 2>&1; then
  lists=$(mktemp -d)
  o=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 "-oDir::State::Lists=$lists")
  mkdir -p "$lists/partial"
  apt-get "${o[@]}" update -qq
  (cd .gl && apt-get "${o[@]}" download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
  rm -rf "$lists"
fi
# The carried libraries are for the carried programs only (the GPU machine's own python3 and
# dpkg keep theirs): each runs through this wrapper.
cat > .gpu/with-libs <<'SH'
#!/bin/sh
here=$(dirname "$(readlink -f "$0")")
LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$@"
SH
chmod +x .gpu/with-libs
cp bench/gpu/run.sh .gpu/run.sh
du -sh .gpu .gl
echo "pack: .gpu/ and .gl/ ready; on the GPU machine run: bash .gpu/run.sh"
