#!/usr/bin/env bash
# Installs Debian's nodejs and npm (the editor grammar tests' tool runs on them) when npm is missing.
# Sourced by ./run-tests; a failure leaves the grammar tests to report the missing tool.
if ! command -v npm >/dev/null 2>&1; then
    echo "npm not found: installing Debian's nodejs and npm packages (for the editor grammar tests)" >&2
    if [ "$(id -u)" -eq 0 ]; then sudo_cmd=""; else sudo_cmd="sudo"; fi
    $sudo_cmd apt-get update -qq >&2 && DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq nodejs npm >&2 \
        || echo "could not install npm; install it with: apt-get install -y nodejs npm" >&2
fi
