# Sourced by tools/setup*: download a Debian source package through a private APT configuration.
# The configuration lives in $1 (its own deb-src list, index lists and caches, an empty parts dir so
# /etc/apt/sources.list.d is not read); the machine's /etc/apt is never written.
#
#   private_apt_fetch APT_DIR SUITES PACKAGE VERSION WORK
# SUITES: space-separated suites of deb.debian.org (e.g. "bookworm bookworm-updates" or "trixie").
# Leaves PACKAGE_VERSION's orig tarball (and .dsc/.debian tarball where the mirror has them) in WORK and
# checks the orig tarball's SHA256 against the signed Sources index (some mirrors lack the .dsc).

private_apt_fetch() {
  local apt_dir=$1 suites=$2 package=$3 version=$4 work=$5
  mkdir -p "$apt_dir/sources.list.d" "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial"
  : > "$apt_dir/sources.list"
  local suite
  for suite in $suites; do
    echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $suite main" \
      >> "$apt_dir/sources.list"
  done
  chmod 755 "$apt_dir" "$apt_dir/sources.list.d" "$apt_dir/lists" "$apt_dir/cache" "$apt_dir/cache/archives"
  chmod 644 "$apt_dir/sources.list"
  PRIVATE_APT=(
    -o "Dir::Etc::SourceList=$apt_dir/sources.list"
    -o "Dir::Etc::SourceParts=$apt_dir/sources.list.d"
    -o "Dir::State::Lists=$apt_dir/lists"
    -o "Dir::Cache=$apt_dir/cache"
  )
  chmod 755 "$work"
  if [ "$(id -u)" = 0 ] && getent passwd _apt >/dev/null; then
    # As root, apt downloads as user _apt. If _apt cannot reach the lists or $work (a cache below a
    # private home), download as root instead, as apt itself would, with a warning.
    chown _apt "$work"
    if command -v runuser >/dev/null &&
       ! { runuser -u _apt -- test -x "$apt_dir/lists" && runuser -u _apt -- test -w "$work"; } 2>/dev/null; then
      PRIVATE_APT+=(-o APT::Sandbox::User=root)
    fi
  fi
  if ! apt-get "${PRIVATE_APT[@]}" update -qq; then
    echo "setup: ERROR: could not fetch the $suites source index into $apt_dir" >&2
    return 1
  fi
  # apt-get fails when any file of the package is missing on the mirror (the .dsc of trixie's lammps is);
  # what counts is the orig tarball, checked below against the index.
  (cd "$work" && apt-get "${PRIVATE_APT[@]}" source --download-only -qq "$package=$version" >/dev/null 2>&1) || true
  local origs=("$work/${package}_"*.orig.tar.*)
  local orig=${origs[0]}
  if [ ! -f "$orig" ]; then
    echo "setup: ERROR: could not download the $package source package $version from $suites" >&2
    return 1
  fi
  local expected
  expected=$(apt-cache "${PRIVATE_APT[@]}" showsrc "$package" |
             awk -v f="$(basename "$orig")" -v v="$version" '
               /^$/ {ver = ""} /^Version:/ {ver = $2}
               /^Checksums-Sha256:/ {s = 1; next} /^[^ ]/ {s = 0}
               s && ver == v && $3 == f {print $1; exit}')
  if [ -z "$expected" ] || [ "$(sha256sum "$orig" | cut -d' ' -f1)" != "$expected" ]; then
    echo "setup: ERROR: $(basename "$orig") does not match the SHA256 of the $suites Sources index" >&2
    return 1
  fi
  PRIVATE_APT_ORIG=$orig
}
