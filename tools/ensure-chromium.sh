#!/usr/bin/env bash
# Installs Debian's chromium (headless browser of the timeline test) when it is missing.
# Sourced by ./run-tests; a failure leaves the timeline test to report the missing browser.
if ! command -v chromium >/dev/null 2>&1; then
    echo "chromium not found: installing Debian's chromium package (for the timeline test)" >&2
    if [ "$(id -u)" -eq 0 ]; then sudo_cmd=""; else sudo_cmd="sudo"; fi
    $sudo_cmd apt-get update -qq >&2 && DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq chromium >&2 \
        || echo "could not install chromium; install it with: apt-get install -y chromium" >&2
fi
