#!/usr/bin/env bash
# Installs Debian's maven package (3.8.7) when /usr/bin/mvn is missing: masl-maven-plugin's tests build a
# project with it (and with a current Maven the build unpacks itself). Sourced by ./run-tests.
if [ ! -x /usr/bin/mvn ]; then
    echo "Debian's Maven not found: installing its maven package" >&2
    if [ "$(id -u)" -eq 0 ]; then sudo_cmd=""; else sudo_cmd="sudo"; fi
    $sudo_cmd apt-get update -qq >&2 && DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq maven >&2 \
        || { echo "could not install maven; install it with: apt-get install -y maven" >&2; exit 64; }
fi
