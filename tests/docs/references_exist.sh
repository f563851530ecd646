#!/usr/bin/env bash
# Every file the documentation names or links exists, every link's anchor is a heading of the
# page it names, and every chapter of the design document (docs/design/) the code cites exists
# with the section it names, so that from a document or a comment the next file is one hop away.
#
#   references_exist.sh REPOSITORY_ROOT
#
# A file reference is a `backticked` path in README.md, docs/*.md or bench/**/README.md that
# ends in a source, script or document extension. It resolves as a path from the repository
# root or the document's folder, as an include path (`edgewise/draw.hpp`), or as the tail of a
# source file's path: of exactly one when it names a folder (`draw/draw_kernels.cpp`), of at least one
# when it is a bare name (`summary.txt`, one per results folder). A citation is
# `docs/design/CHAPTER.md`, or `docs/design/CHAPTER.md, "Heading"`, in any source file of
# kernels/, tests/, bench/, tools/ or testing/.
# shellcheck disable=SC2016 # the backticks are Markdown's, matched literally
set -euo pipefail

root=$1
cd "$root"
failures=0
fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# The tracked sources: every file outside the build directories.
sources=$(find kernels tests bench tools testing docs cmake -type f | sort)
documents=(README.md docs/*.md bench/README.md bench/results/README.md)
for document in "${documents[@]}"; do
  folder=$(dirname "$document")
  while read -r path; do
    [[ -e $path || -e $folder/$path || -e kernels/include/$path ]] && continue
    matches=$(grep -cE "(^|/)${path//./\\.}\$" <<<"$sources" || true)
    # A bare name (`summary.txt`, one per results folder) may stand for several files.
    if [[ $path == */* ]]; then
      ((matches == 1)) || fail "$document names \`$path\`: $matches files match"
    else
      ((matches >= 1)) || fail "$document names \`$path\`, which does not exist"
    fi
  done < <(grep -oE '`[A-Za-z0-9_./-]+\.(hpp|cpp|cmake|sh|py|md|txt)`' "$document" | tr -d '`' |
    sort -u)
done

# GitHub's anchor for each heading of a Markdown file: lower case, punctuation dropped, spaces
# as hyphens.
anchors_of() {
  grep -E '^#+ ' "$1" | sed -E 's/^#+ //' | tr '[:upper:]' '[:lower:]' |
    sed -E 's/[^a-z0-9 _-]//g; s/ /-/g'
}

# A Markdown link, [text](target), resolves from the document's folder to a file or folder, and
# its #anchor, where it has one into a Markdown file, to one of that file's headings.
for document in "${documents[@]}"; do
  folder=$(dirname "$document")
  while read -r target; do
    [[ $target =~ ^(https?|mailto): ]] && continue
    path=${target%%#*}
    anchor=
    [[ $target == *#* ]] && anchor=${target#*#}
    resolved=$document
    [[ -n $path ]] && resolved=$folder/$path
    if [[ ! -e $resolved ]]; then
      fail "$document links to $target, which does not exist"
      continue
    fi
    if [[ -n $anchor && $resolved == *.md ]] && ! anchors_of "$resolved" | grep -qxF "$anchor"; then
      fail "$document links to $target: no heading of $resolved has the anchor #$anchor"
    fi
  done < <(grep -oE '\]\([^)[:space:]]+\)' "$document" | sed -E 's/^\]\((.*)\)$/\1/' | sort -u)
done

# The design document's chapters the code cites, and the sections it names in them:
# `docs/design/threads.md`, `docs/design/rasterization.md, "Tiles and masks"`.
while IFS= read -r citation; do
  chapter=${citation%%.md*}.md
  if [[ ! -f $chapter ]]; then
    fail "code cites $chapter, which does not exist"
    continue
  fi
  [[ $citation == *\"* ]] || continue
  section=${citation#*\"}
  section=${section%\"}
  grep -E '^#+ ' "$chapter" | sed -E 's/^#+ //' | grep -qxF "$section" ||
    fail "code cites $chapter, \"$section\", which is not a heading there"
done < <(grep -rhoE --exclude=references_exist.sh 'docs/design/[A-Za-z0-9_-]+\.md(,? "[^"]+")?' \
  kernels tests bench tools testing | sort -u)
# Sections are cited in their chapter, not in the index.
while IFS= read -r citation; do
  fail "code cites $citation: sections live in the chapters under docs/design/"
done < <(grep -rhoE --exclude=references_exist.sh 'docs/DESIGN\.md,? "[^"]+"' kernels tests bench tools \
  testing | sort -u)

if ((failures > 0)); then
  echo "$failures broken references" >&2
  exit 1
fi
echo "every referenced file, link and cited section exists"
