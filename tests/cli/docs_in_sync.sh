#!/bin/sh
# docs_in_sync.sh PENUMBRA CLI_MD
# Issue 26 B19: docs/cli.md's sample `penumbra check` table lists exactly the
# registered checks, in the order `check` runs them (the registry's list, as
# the unknown-module error names it). Needs no GL context.
set -u
penumbra=$1 cli_md=$2
fail() { printf 'docs_in_sync: %s\n' "$1"; exit 1; }
registered=$("$penumbra" check no-such-module 2>&1 | sed -n 's/.*expected one of //p' | tr -d ' ' | tr ',' '\n')
[ -n "$registered" ] || fail "could not read the registered checks from penumbra"
documented=$(awk '/^module +cases +worst error/ { table = 1; next } table && /^```/ { exit } table { print $1 }' "$cli_md")
[ -n "$documented" ] || fail "no check table in $cli_md"
if [ "$registered" != "$documented" ]; then
  printf 'registered:\n%s\ndocumented in %s:\n%s\n' "$registered" "$cli_md" "$documented"
  fail "docs/cli.md's check table differs from the registered checks: run \`penumbra check\` and paste its table"
fi
echo "docs_in_sync: ok ($(printf '%s\n' "$registered" | wc -l) checks)"
