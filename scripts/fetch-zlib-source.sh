#!/usr/bin/env bash
# Fetches Debian 12's zlib source (the upstream tarball of zlib1g 1:1.2.13.dfsg) into a cache outside the
# repository, for the browser module (web/module), which compiles it with Emscripten: Debian's emscripten
# has no zlib of its own and would download its port from the network. Checked against Debian's sha256.
#
#   scripts/fetch-zlib-source.sh       # prints the source folder
#
# Idempotent: a second run finds the folder and only prints it.
set -euo pipefail

name=zlib-1.2.13.dfsg
tarball=zlib_1.2.13.dfsg.orig.tar.bz2
sha256=71feb7947e3c00ef125f83b79a4e529bde31171e5babe48b391f06758d1ab0a1
cache=${CADNURBS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/cadnurbs}
source="$cache/$name"

if [ ! -f "$source/inflate.c" ]; then
  mkdir -p "$cache"
  if [ ! -f "$cache/$tarball" ] || ! echo "$sha256  $cache/$tarball" | sha256sum -c --status; then
    echo "fetch-zlib-source: downloading $tarball into $cache" >&2
    curl -fsSL -o "$cache/$tarball.part" "http://deb.debian.org/debian/pool/main/z/zlib/$tarball"
    echo "$sha256  $cache/$tarball.part" | sha256sum -c --status \
      || { echo "fetch-zlib-source: $tarball does not match Debian's sha256" >&2; rm -f "$cache/$tarball.part"; exit 1; }
    mv "$cache/$tarball.part" "$cache/$tarball"
  fi
  staging=$(mktemp -d "$cache/unpack.XXXXXX")
  trap 'rm -rf "$staging"' EXIT
  tar -xjf "$cache/$tarball" -C "$staging"
  rm -rf "$source"
  mv "$staging/$name" "$source"
fi
echo "$source"
