#!/usr/bin/env bash
# Installs the Debian packages the checks need, where they are missing and we may install
# (root with apt-get). Otherwise it says which checks will be skipped; it never fails the build.
#   tools/ensure-packages.sh <command>:<package> ...
set -u
missing=()
for pair in "$@"; do
    command=${pair%%:*} package=${pair#*:}
    if ! command -v "$command" >/dev/null 2>&1 && ! dpkg -s "$package" >/dev/null 2>&1; then
        missing+=("$package")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "Installing ${missing[*]} ..."
    export DEBIAN_FRONTEND=noninteractive
    if ! { apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; }; then
        echo "WARNING: could not install ${missing[*]}; the checks that need them will be skipped."
    fi
else
    echo "NOTE: ${missing[*]} not installed and not root; the checks that need them will be skipped" \
         "(install with: sudo apt-get install ${missing[*]})."
fi
exit 0
