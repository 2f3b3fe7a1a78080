#!/bin/sh
# SPDX-License-Identifier: MIT
# tools/check-spdx.sh - every source, header, script and build file of the
# project names its licence in its first lines; the closing line counts
# the files checked ("N passed, N failed") for tools/run-tests.sh.
#
#   tools/check-spdx.sh            check the files git tracks
set -u
cd "$(dirname "$0")/.."
passed=0
failed=0
for file in $(git ls-files); do
    case "$file" in
        *.c|*.h|*.cpp|*.hpp|*.S|*.py|*.sh|*.mk|*.ld|*.cmake|*.yml|*.yaml|*.properties|*.txt|Makefile|*/Makefile|CMakeLists.txt|*/CMakeLists.txt|Kconfig|*/Kconfig|.ci/run) ;;
        *.json) # JSON has no comments: the manifest's own licence field
            if grep -q '"license": *"MIT"' "$file"; then passed=$((passed + 1)); else
                echo "FAIL $file: no \"license\": \"MIT\""; failed=$((failed + 1)); fi
            continue ;;
        *) continue ;;
    esac
    # data files that happen to end in .txt are not sources
    case "$file" in
        *.txt) case "$file" in */CMakeLists.txt|CMakeLists.txt|sources.txt|*/sources.txt) ;; *) continue ;; esac ;;
    esac
    if head -n 3 "$file" | grep -q 'SPDX-License-Identifier: MIT'; then
        passed=$((passed + 1))
    else
        echo "FAIL $file: no SPDX-License-Identifier: MIT in its first three lines"
        failed=$((failed + 1))
    fi
done
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
