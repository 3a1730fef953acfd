# Keeps docs/benchmarks.md a page of current results (issue #30), in a fraction of a second:
#   - it is under LIMIT bytes (40 KB), so that a reader finds the results in five minutes;
#   - it holds no measurement history: no "Nth round" heading, no anchor of the history file
#     or of the old performance section, no word of bench/solver_performance.md (the history
#     is docs/performance-history.md, written by hand);
#   - every image and every local page it links to exists.
# The page is written by scripts/bench.sh; when this fails, change the script, not the page.
#
#   cmake -D PAGE=docs/benchmarks.md -D LIMIT=40000 -P tests/benchmarks_page_check.cmake
if(NOT DEFINED PAGE OR NOT DEFINED LIMIT)
  message(FATAL_ERROR "usage: cmake -D PAGE=<docs/benchmarks.md> -D LIMIT=<bytes> -P benchmarks_page_check.cmake")
endif()
if(NOT EXISTS "${PAGE}")
  message(FATAL_ERROR "${PAGE} does not exist: scripts/bench.sh writes it")
endif()

set(problems "")

file(SIZE "${PAGE}" size)
if(NOT size LESS LIMIT)
  # (No semicolons in these messages: CMake would split them into list items.)
  list(APPEND problems "${PAGE} is ${size} bytes, and the limit is ${LIMIT} bytes (40 KB): scripts/bench.sh should "
                       "move long tables to docs/data/benchmark-tables.md and history to docs/performance-history.md")
endif()

# History markers: a heading naming a round ("Seventeenth round: …", "3rd round"), the anchors of
# the history file and of the page's old performance section, the old history file's name.
file(STRINGS "${PAGE}" lines)
set(line_number 0)
foreach(line IN LISTS lines)
  math(EXPR line_number "${line_number} + 1")
  if(line MATCHES "^#+ .*(st|nd|rd|th) [Rr]ound" OR line MATCHES "\\{#(history-|benchmarks-performance)"
     OR line MATCHES "solver_performance\\.md")
    list(APPEND problems "${PAGE}:${line_number}: history on the page of current results (it belongs in "
                         "docs/performance-history.md): ${line}")
  endif()
endforeach()

# Images (<img src="…">) and links to local files ([text](path) or [text](path#anchor)).
# "](" becomes "@link(" first: a "]" in a CMake list item would stop the list splitting.
get_filename_component(page_dir "${PAGE}" DIRECTORY)
file(READ "${PAGE}" text)
string(REPLACE "](" "@link(" text "${text}")
string(REGEX MATCHALL "src=\"[^\"]+\"" images "${text}")
string(REGEX MATCHALL "@link\\([^)# ]+[)#]" links "${text}")
foreach(target IN LISTS images links)
  string(REGEX REPLACE "^src=\"([^\"]+)\"$" "\\1" target "${target}")
  string(REGEX REPLACE "^@link\\(([^)# ]+)[)#]$" "\\1" target "${target}")
  if(target MATCHES "^[a-z]+:")  # http:, https:, mailto:
    continue()
  endif()
  if(NOT EXISTS "${page_dir}/${target}")
    list(APPEND problems "${PAGE} refers to ${target}, which does not exist (relative to ${page_dir})")
  endif()
endforeach()

if(problems)
  list(JOIN problems "\n  " report)
  message(FATAL_ERROR "docs/benchmarks.md check failed:\n  ${report}")
endif()
message(STATUS "${PAGE}: ${size} bytes (limit ${LIMIT}), no history, every image and local link found")
