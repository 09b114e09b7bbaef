#!/bin/sh
# shader-cache.sh COMPILER ARGS... -o OUTPUT INPUT: runs vkd3d-compiler through a cache of
# compiled shaders (set up in cmake/FirmamentShaders.cmake), the shaders' counterpart of ccache.
# The key is the compiler's version, its arguments less the output's and the input's names, and
# the source as vkd3d-compiler's own preprocessor expands it (so an edited header changes the
# key, and a wrapper of the same text elsewhere, such as hot reload's, finds the build's entry). With
# FIRMAMENT_SHADER_CACHE unset, or a source that does not preprocess, it only runs the
# compiler, whose messages and exit status are passed on unchanged.
set -u
compiler=$1
shift
cache=${FIRMAMENT_SHADER_CACHE:-}
[ -n "$cache" ] || exec "$compiler" "$@"

# The arguments without "-o OUTPUT" and the input, the last one.
output=
input=
keyed=
previous=
for argument in "$@"; do
    if [ "$previous" = "-o" ]; then
        output=$argument
    elif [ "$argument" != "-o" ]; then
        [ -z "$input" ] || keyed="$keyed $input"  # the one before was not the last
        input=$argument
    fi
    previous=$argument
done
[ -n "$output" ] || exec "$compiler" "$@"

preprocessed=$(mktemp) || exec "$compiler" "$@"
if ! "$compiler" -x hlsl -E "$input" >"$preprocessed" 2>/dev/null; then
    rm -f "$preprocessed"
    exec "$compiler" "$@"
fi
key=$({
    "$compiler" --version
    echo "$keyed"
    cat "$preprocessed"
} | sha256sum | cut -c1-40)
rm -f "$preprocessed"
entry="$cache/$(echo "$key" | cut -c1-2)/$key.cso"
if [ -f "$entry" ]; then
    touch "$entry" 2>/dev/null  # last used now: tools/build removes entries unused for 30 days
    cp "$entry" "$output.tmp.$$" && mv "$output.tmp.$$" "$output" && exit 0
fi
"$compiler" "$@" || exit $?
mkdir -p "$cache/$(echo "$key" | cut -c1-2)" 2>/dev/null &&
    cp "$output" "$entry.tmp.$$" 2>/dev/null && mv "$entry.tmp.$$" "$entry" 2>/dev/null
exit 0
