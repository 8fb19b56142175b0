# Sourced by the CI scripts.

# need CMD PACKAGE LOG: installs the Debian package PACKAGE (apt-get, with
# one `apt-get update` if the first try fails) unless CMD is on PATH; the
# output goes to LOG, shown on failure.
need() {
  local cmd=$1 package=$2 log=$3
  command -v "$cmd" > /dev/null && return 0
  echo "installing $package"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -q "$package" > "$log" 2>&1 \
    || { apt-get update -q >> "$log" 2>&1 && apt-get install -y -q "$package" >> "$log" 2>&1; } \
    || { tail -20 "$log"; return 1; }
}
