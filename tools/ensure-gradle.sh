#!/usr/bin/env bash
# Installs Debian's gradle package (4.4.1) when no `gradle` is on the PATH. Sourced by ./masl and ./run-tests.
if ! command -v gradle >/dev/null 2>&1; then
    echo "gradle not found: installing Debian's gradle package" >&2
    if [ "$(id -u)" -eq 0 ]; then sudo_cmd=""; else sudo_cmd="sudo"; fi
    $sudo_cmd apt-get update -qq >&2 && DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq gradle >&2 \
        || { echo "could not install gradle; install it with: apt-get install -y gradle" >&2; exit 64; }
fi
