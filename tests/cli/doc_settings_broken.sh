#!/bin/sh
# doc_settings_broken.sh ROOT WORKDIR
# doc_snippets.py's settings check (issue 53) fails on a copy of the docs where a settings field's
# comment names no default, and where a field is gone from the page, and passes on the library.
set -u
root=$1 work=$2
rm -rf "$work" && mkdir -p "$work/tests" || exit 1
cp -r "$root/glsl" "$root/docs" "$work/" && cp -r "$root/tests/docs" "$work/tests/" || exit 1
python3 "$root/tests/doc_snippets.py" --settings-only "$work" || { echo "the library's pages fail"; exit 1; }
sed -i 's|  int filterSamples;   // default 32: the PCF|  int filterSamples;   // 32: the PCF|' "$work/docs/modules/vogel_pcss.md"
sed -i '/  int budget;       \/\/ default 4096/d' "$work/docs/modules/backprojection.md"
out=$(python3 "$root/tests/doc_snippets.py" --settings-only "$work") && { echo "the broken copy passed"; exit 1; }
echo "$out"
echo "$out" | grep -q "PnVogelPcssSettings.filterSamples: its comment names no default" || { echo "missing default not named"; exit 1; }
echo "$out" | grep -q "PnBackprojectionSettings.budget not on a line of its own" || { echo "missing field not named"; exit 1; }
echo "$out" | grep -q "settings structs: 2 failures" || { echo "expected 2 failures"; exit 1; }
