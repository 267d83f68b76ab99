# Shared by the hostile-text scripts (sourced, not run): hostile_reports.sh, hostile_full_run.sh.
# Reads PADDY SOURCE_DIR WORK_DIR from the script's arguments into paddy, src and work (emptied,
# made, entered, absolute), defines fail (the message names the script) and canary = $work/CANARY,
# the file a command smuggled in through a hostile string would create.
script_name=$(basename "$0" .sh)
paddy=${1:?usage: $script_name.sh PADDY SOURCE_DIR WORK_DIR}
src=${2:?}
work=${3:?}
fail() { echo "$script_name: FAIL: $*" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cd "$work"
work=$(pwd)
canary="$work/CANARY"

# check_page DIR PAGE: PAGE (relative to DIR) is well-formed XHTML and every image it shows exists
# in DIR (the src unescaped); prints the number of images in `images`.
check_page() {
  local dir=$1 page=$2 img
  xmllint --noout "$dir/$page" || fail "$page is not well-formed"
  images=0
  while IFS= read -r img; do
    img=$(printf '%s' "$img" | sed 's/&amp;/\&/g; s/&lt;/</g; s/&gt;/>/g; s/&quot;/"/g; s/&#39;/'"'"'/g')
    [ -s "$dir/$img" ] || fail "$page: image $img is missing"
    images=$((images + 1))
  done < <(grep -o '<img src="[^"]*"' "$dir/$page" | sed 's/^<img src="//; s/"$//')
}
