#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image: it installs what
# grading needs. close2gl comes as a release binary shipped in the autograder's zip beside this
# file (`close2gl`, built with `cargo build --release` on a Linux machine like Gradescope's), or,
# without one, is built from the source shipped as `close2gl-src/` (rustup and a compile: about
# ten minutes). CLOSE2GL_PREFIX installs somewhere other than /usr/local (a test does).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
prefix=${CLOSE2GL_PREFIX:-/usr/local}

# The students' programs are C: a compiler, and python3 for run_autograder's messages.
if ! command -v cc >/dev/null || ! command -v python3 >/dev/null; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends gcc libc6-dev python3
fi

mkdir -p "$prefix/bin"
if [ -x "$here/close2gl" ]; then
  install -m 755 "$here/close2gl" "$prefix/bin/close2gl"
elif [ -d "$here/close2gl-src" ]; then
  if ! command -v cargo >/dev/null; then
    apt-get install -y -qq --no-install-recommends curl ca-certificates
    curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal
    . "$HOME/.cargo/env"
  fi
  cargo install --locked --path "$here/close2gl-src" --root "$prefix"
else
  echo "setup.sh: expected a close2gl binary or close2gl-src/ beside this script" >&2
  exit 1
fi
"$prefix/bin/close2gl" --version
