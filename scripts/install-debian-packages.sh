#!/usr/bin/env bash
# install-debian-packages.sh LABEL PACKAGE...: apt-get installs those of PACKAGE... that dpkg does not list
# as installed (one apt-get update, no recommends); prints "LABEL: ..." either way. Root, or sudo.
# Shared by scripts/setup.sh and scripts/setup-bench.sh.
set -euo pipefail

label=$1
shift
sudo_if_needed() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "$label: installing ${missing[*]}"
  sudo_if_needed apt-get update -q
  sudo_if_needed env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "$label: Debian packages present"
fi
