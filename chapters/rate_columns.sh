# The level columns of a local-rate table, shared by chapters/rate_table.sh and chapter 6's
# rate_table.sh (sourced): one column per pair of levels, "0-1", "1-2", ...
#
#   level_header MOST   " 0-1 | 1-2 | ... |" for MOST pairs
#   level_rule MOST     "---|---|...|" for MOST pairs
level_header() {
  local k text=""
  for ((k = 0; k < $1; ++k)); do text+=" $k-$((k + 1)) |"; done
  printf '%s' "$text"
}
level_rule() {
  local k text=""
  for ((k = 0; k < $1; ++k)); do text+="---|"; done
  printf '%s' "$text"
}
