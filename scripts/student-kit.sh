#!/usr/bin/env bash
# Writes the students' copy of the repository: every file except those below
# lectures/instructors/, the one folder that holds answers (the assignments'
# solutions and tried answers, the filled-in student templates, and the page
# that states the answers; docs/instructors.md says how to hand out the copy).
#
#   scripts/student-kit.sh [--output FILE] [--worktree | REV]
#
#   --output FILE  where to write the archive (default: stepwise-students.tar.gz
#                  in the current directory)
#   REV            the commit to copy, as `git archive` reads it (default HEAD)
#   --worktree     copy the files as they are now instead of a commit: tracked
#                  files and new files git does not ignore (to check uncommitted work)
#
# The archive is a gzip-compressed tar file whose files all sit below one
# folder, stepwise/ (`tar -xzf stepwise-students.tar.gz` makes stepwise/).
# Works from any directory inside the repository or outside it.
#
# Exit status: 0 when the archive was written; 2 for a bad command line, a REV
# that is not a commit, an output folder that does not exist, or a checkout
# that is not a git repository; 1 when writing the archive failed.
set -uo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
answers=lectures/instructors
prefix=stepwise/

usage() {
    echo "usage: scripts/student-kit.sh [--output FILE] [--worktree | REV]" >&2
    exit 2
}

output=stepwise-students.tar.gz
rev=
worktree=false
while (($# > 0)); do
    case $1 in
        --output | -o)
            (($# >= 2)) || { echo "student-kit: $1 needs a file name" >&2; usage; }
            output=$2
            shift 2
            ;;
        --worktree)
            worktree=true
            shift
            ;;
        -h | --help)
            sed -n '2,21s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"
            exit 0
            ;;
        -*)
            echo "student-kit: unknown option '$1'" >&2
            usage
            ;;
        *)
            [[ -z $rev ]] || { echo "student-kit: one REV only, got '$rev' and '$1'" >&2; usage; }
            rev=$1
            shift
            ;;
    esac
done
if [[ $worktree == true && -n $rev ]]; then
    echo "student-kit: --worktree copies the files as they are now; it takes no REV ('$rev')" >&2
    usage
fi

if ! git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    echo "student-kit: $root is not a git repository: the kit is made from git's list of files" >&2
    exit 2
fi
output_dir=$(dirname -- "$output")
if [[ ! -d $output_dir ]]; then
    echo "student-kit: cannot write '$output': there is no folder '$output_dir'" >&2
    exit 2
fi
output=$(cd "$output_dir" && pwd)/$(basename -- "$output")

if [[ $worktree == true ]]; then
    # Tracked and new files, minus the answers and minus files deleted but not yet committed.
    files=()
    while IFS= read -r -d '' file; do
        [[ -f $root/$file ]] && files+=("$file")
    done < <(git -C "$root" ls-files -z --cached --others --exclude-standard -- . ":(exclude)$answers")
    if ! printf '%s\0' "${files[@]}" | sort -zu |
        tar -C "$root" --transform "s,^,$prefix,S" --null -T - -czf "$output"; then
        echo "student-kit: writing $output failed" >&2
        exit 1
    fi
    what="the working tree"
else
    rev=${rev:-HEAD}
    if ! git -C "$root" rev-parse --verify --quiet "$rev^{commit}" > /dev/null; then
        echo "student-kit: '$rev' is not a commit of $root" >&2
        exit 2
    fi
    if ! git -C "$root" archive --format=tar.gz --prefix="$prefix" -o "$output" "$rev" -- . ":(exclude)$answers"; then
        echo "student-kit: writing $output failed" >&2
        exit 1
    fi
    what="commit $(git -C "$root" rev-parse --short "$rev")"
fi
count=$(tar -tzf "$output" | grep -vc '/$')
echo "student-kit: wrote $output: $count files of $what, without $answers/"
