# Sourced by the stills benchmarks: makes mandelbulber2 (Debian 2.20, the peer they compare with)
# available, installing the Debian package when it is missing. Sets peer=1 when it can run, else
# peer=0 with a message saying why, so the caller times fraktal alone. Needs $tmp (a scratch folder).
if ! command -v mandelbulber2 > /dev/null; then
  echo "mandelbulber2 is missing: installing the Debian package" >&2
  sudo=(); [[ $(id -u) -eq 0 ]] || sudo=(sudo -n)
  "${sudo[@]}" apt-get install -y mandelbulber2 > "$tmp/apt.log" 2>&1 ||
    { "${sudo[@]}" apt-get update > /dev/null 2>&1 && "${sudo[@]}" apt-get install -y mandelbulber2 > "$tmp/apt.log" 2>&1; } || true
fi
peer=1
if ! command -v mandelbulber2 > /dev/null; then
  peer=0
  echo "mandelbulber2 could not be installed (apt-get install -y mandelbulber2: $(tail -1 "$tmp/apt.log" 2>/dev/null)):" \
    "skipping the comparison, timing fraktal alone" >&2
fi
