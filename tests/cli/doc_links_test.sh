#!/usr/bin/env bash
# Every page of docs/ the tree cites exists: a docs/ page path in code, comments, scripts and
# pages, and every relative link between the pages of docs/. The pages' names are lower case, so
# a placeholder such as docs/X.md in upper case is not a citation. A renamed or missing page is a
# comment that sends the reader nowhere.
# Usage: doc_links_test.sh PROJECT_ROOT
set -u
root=$1
cd "$root" || exit 1
failed=0
files=$(git ls-files 2>/dev/null || find . -type f -not -path './build*' -not -path './.git/*')
while read -r cited; do
  [ -e "$cited" ] || { echo "FAILED: $cited is cited but does not exist:" >&2
                       grep -rln -- "$cited" $files | sed 's/^/  in /' >&2; failed=$((failed + 1)); }
done < <(grep -ohE "docs/[a-z0-9_-]+\.md" $files | sort -u)
for page in docs/*.md; do
  while read -r link; do
    [ -e "docs/$link" ] || { echo "FAILED: $page links to $link, which does not exist" >&2
                             failed=$((failed + 1)); }
  done < <(grep -ohE "\]\([a-z0-9_-]+\.md" "$page" | sed 's/^](//' | sort -u)
done
echo "doc links: $failed missing"
[ "$failed" -eq 0 ]
