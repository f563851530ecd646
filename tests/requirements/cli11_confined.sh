#!/usr/bin/env bash
# CLI11 stays behind tools/common/command_line.hpp: only command_line.cpp, run_tool.cpp and
# tool_app (which run_tool.cpp alone includes) include it, so that no other unit compiles its
# header (several seconds each at -O3, more under the sanitizers). $1: the source tree.
set -euo pipefail
cd "$1"
allowed='^tools/common/(command_line\.cpp|run_tool\.cpp|tool_app\.cpp|tool_app\.hpp)$'
found=$(grep -rlE '#include[[:space:]]*<CLI/' --include='*.cpp' --include='*.hpp' \
  kernels tools tests testing bench | grep -vE "$allowed" || true)
found+=" "$(grep -rlE '#include[[:space:]]*"common/tool_app\.hpp"' --include='*.cpp' --include='*.hpp' \
  kernels tools tests testing bench | grep -vE "$allowed" || true)
if [[ -n ${found// /} ]]; then
  echo "CLI11 reached outside tools/common/command_line.hpp's files:" $found >&2
  exit 1
fi
echo "CLI11 included only by tools/common/command_line.cpp, run_tool.cpp and tool_app"
