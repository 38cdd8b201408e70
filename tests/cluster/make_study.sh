# Sourced by the cluster tests: writes $work/study.toml, the shipped example study with
# absolute paths and 2 s runs, and $work/whole, the unsharded study to compare with.
make_study() {
  local source=$1 work=$2 bin=$3
  sed -e "s#\"../70ton-loaded.toml\"#\"$source/scenarios/70ton-loaded.toml\"#" -e 's#"4 s"#"2 s"#' \
    "$source/scenarios/studies/side-bearing-clearance.toml" > "$work/study.toml"
  "$bin" study "$work/study.toml" --out "$work/whole" --jobs 2 > "$work/whole.log" 2>&1
}
compare_study() {
  local a=$1 b=$2 f
  for f in study.csv study.json; do
    cmp "$a/$f" "$b/$f" || { echo "FAIL: $b/$f differs from $a/$f"; return 1; }
    echo "$b/$f is byte-identical to $a/$f ($(wc -c < "$a/$f") bytes)"
  done
}
