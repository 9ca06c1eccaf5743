#!/usr/bin/env bash
# Checks that the documentation holds together (the CTest test doc_check):
#   1. every relative link of README.md, CHANGELOG.md, CONTRIBUTING.md and
#      doc/**/*.md resolves: the file or directory exists and, for a
#      "#heading" part, the target has that heading (GitHub's anchors);
#   2. doc/index.md links every page of doc/;
#   3. every "<!-- copy: NAME -->" block equals the recipe NAME of any
#      document (scripts/doc-block.sh), so a copy shown for reading cannot
#      drift from the recipe that runs;
#   4. no document points into ../shared (reference data beside the
#      repository, not part of it);
#   5. user-facing text carries no development history: README.md, doc/
#      outside doc/dev/, the public header and the sources of the CLI, the
#      Fortran layer and the core name no issue, item or stop;
#   6. README.md stays an entry point: at most 200 lines;
#   7. timings live in doc/performance.md only (no load average or stamp
#      elsewhere but doc/dev/), and every timing table there sits in a
#      "<!-- timing: SECTION -->" block of scripts/bench-report.sh under a
#      stamp that names a commit and a load average below 1.5, or says it
#      is to be re-measured.
# usage: doc-check.sh [SOURCE_DIR]
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
export LC_ALL=C
problems=0
problem() { echo "doc-check: $*" >&2; problems=$((problems + 1)); }

mapfile -t docs < <({ printf '%s\n' README.md CHANGELOG.md CONTRIBUTING.md; find doc -name '*.md'; } | sort)

# The text of a document outside fenced code blocks.
prose() { awk '/^```/ { fenced = !fenced; next } !fenced' "$1"; }

# GitHub's anchors of a document's headings, one per line: lower case,
# punctuation dropped, spaces as hyphens, repeats numbered -1, -2, ...
anchors() {
  prose "$1" | sed -n 's/^#\{1,6\} \{1,\}//p' | sed 's/[[:space:]]*$//' |
    tr '[:upper:]' '[:lower:]' | sed 's/[^a-z0-9 _-]//g; s/ /-/g' |
    awk '{ n = seen[$0]++; print (n ? $0 "-" n : $0) }'
}

# 1. Links.
declare -A linked_from_index=()
for doc in "${docs[@]}"; do
  dir=$(dirname "$doc")
  while IFS= read -r target; do
    case "$target" in http://* | https://* | mailto:*) continue ;; esac
    path=${target%%#*}
    anchor=""
    [[ "$target" == *"#"* ]] && anchor=${target#*#}
    if [ -z "$path" ]; then
      resolved=$doc
    else
      resolved=$(realpath -m --relative-to=. "$dir/$path")
    fi
    case "$resolved" in ../*) problem "$doc: link '$target' leaves the repository"; continue ;; esac
    if [ ! -e "$resolved" ]; then
      problem "$doc: link '$target': $resolved does not exist"
      continue
    fi
    [ "$doc" = doc/index.md ] && linked_from_index[$resolved]=1
    if [ -n "$anchor" ]; then
      if [ -d "$resolved" ] || [[ "$resolved" != *.md ]]; then
        problem "$doc: link '$target': only Markdown files have headings"
      elif ! anchors "$resolved" | grep -qxF -- "$anchor"; then
        problem "$doc: link '$target': $resolved has no heading with the anchor #$anchor"
      fi
    fi
  done < <(prose "$doc" | grep -o '\](\([^)]*\))' | sed 's/^](\(.*\))$/\1/; s/ .*//')
done

# 2. The index links every page.
while IFS= read -r page; do
  [ "$page" = doc/index.md ] && continue
  [ -n "${linked_from_index[$page]:-}" ] || problem "doc/index.md does not link $page"
done < <(find doc -name '*.md' | sort)

# 3. Copies equal their recipes.
for doc in "${docs[@]}"; do
  while read -r kind name; do
    [ "$kind" = copy ] || continue
    found=""
    for other in README.md $(find doc -name '*.md' | sort); do
      for k in recipe recipe-ci; do
        if bash scripts/doc-block.sh "$other" list | grep -qx "$k $name"; then
          found="$other $k"
          if ! diff <(bash scripts/doc-block.sh "$other" "$k" "$name") \
                    <(bash scripts/doc-block.sh "$doc" copy "$name") >/dev/null; then
            problem "$doc: the copy of '$name' differs from the $k in $other"
          fi
        fi
      done
    done
    [ -n "$found" ] || problem "$doc: copy of '$name', but no recipe has that name"
  done < <(bash scripts/doc-block.sh "$doc" list)
done

# 4. Nothing points into ../shared.
if grep -n '\.\./shared' "${docs[@]}" | grep -v '^doc/dev/'; then
  problem "the lines above point into ../shared, which is not part of the repository"
fi

# 5. No development history in user-facing text.
history='issue [0-9]|item [0-9]|this stop|stop [0-9]|start of this|not kept|once available|other developers'
if hits=$(grep -rniE "$history" README.md doc capi/include programs/cli fortran core 2>/dev/null |
          grep -v '^doc/dev/'); then
  echo "$hits" >&2
  problem "the lines above carry development history into user-facing text"
fi

# 6. The README is an entry point.
lines=$(wc -l <README.md)
[ "$lines" -le 200 ] || problem "README.md has $lines lines (at most 200)"

# 7. Timings: in doc/performance.md only, each under an honest stamp.
if hits=$(grep -nE 'load average|^\*[Mm]easured (on|by) |^[Ss]tamp:' README.md CHANGELOG.md \
            $(find doc -name '*.md' ! -path 'doc/dev/*' ! -name performance.md | sort)); then
  echo "$hits" >&2
  problem "the lines above hold timings or their stamps: timings live in doc/performance.md"
fi
sections=" $(bash scripts/bench-report.sh --list | tr '\n' ' ') "
while IFS='|' read -r line kind text; do
  case "$kind" in
    unknown) problem "doc/performance.md:$line: no bench-report.sh section '$text'" ;;
    open) problem "doc/performance.md:$line: timing block '$text' has no <!-- end timing -->" ;;
    nostamp) problem "doc/performance.md:$line: a timing block starts without a stamp (*Measured ...*)" ;;
    stamp)
      if ! grep -q 'to be re-measured' <<<"$text" &&
         { ! grep -Eq 'commit [0-9a-f]{7,40}[,;]' <<<"$text" || ! grep -q '(below 1\.5)' <<<"$text" ||
           grep -Eq 'not for the page|uncommitted|\+changes' <<<"$text"; }; then
        problem "doc/performance.md:$line: the stamp names no clean commit and load below 1.5: $text"
      fi ;;
  esac
done < <(awk -v sections="$sections" '
  /^<!-- timing: .* -->$/ {
    name = $3; open = NR; first = 1
    if (index(sections, " " name " ") == 0) print NR "|unknown|" name
    next
  }
  /^<!-- end timing -->$/ { open = 0; next }
  open && first && NF { first = 0; print NR "|" ($0 ~ /^\*Measured / ? "stamp" : "nostamp") "|" $0 }
  END { if (open) print open "|open|" name }' doc/performance.md)

if [ $problems -gt 0 ]; then
  echo "doc-check: $problems problem(s)" >&2
  exit 1
fi
echo "doc-check: ${#docs[@]} documents: links, index, copies and wording hold; README.md $lines lines"
