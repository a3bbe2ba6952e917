#!/usr/bin/env bash
# docs/cli.md is generated from the option tables: fails, with the difference, when it is not what
# `penumbra help --markdown` prints now. Usage: scripts/check-cli-doc.sh PENUMBRA [DOC]
set -uo pipefail
penumbra=$1
doc=${2:-"$(cd "$(dirname "$0")/.." && pwd)/docs/cli.md"}
generated=$("$penumbra" help --markdown) || { echo "check-cli-doc: '$penumbra help --markdown' failed"; exit 1; }
if ! difference=$(diff -u --label docs/cli.md --label "penumbra help --markdown" "$doc" - <<<"$generated"); then
  echo "$difference" | head -n 60
  echo "check-cli-doc: docs/cli.md differs from 'penumbra help --markdown'; regenerate it with"
  echo "  ./build/penumbra help --markdown > docs/cli.md"
  exit 1
fi
echo "check-cli-doc: docs/cli.md is what 'penumbra help --markdown' prints"
