#!/usr/bin/env bash
# A Debian chroot with a newer QGIS than the host's, to run `make demo` and `make test` there (docs/newer-qgis.md).
#
#   sudo scripts/debian_chroot.sh create DIR SUITE   SUITE: sid, forky, trixie or trixie-backports
#   sudo scripts/debian_chroot.sh enter DIR [COMMAND...]   a shell (or COMMAND) inside, with /proc, /sys, /dev
#   sudo scripts/debian_chroot.sh test DIR [TARGET]   clone HEAD to DIR/root/incircu, run `make TARGET` (.ci/run: test)
#   sudo scripts/debian_chroot.sh umount DIR
#
# `create` needs debootstrap on the host (apt-get install debootstrap) and installs only make, git and the CA
# certificates: `make setup` inside installs QGIS and the rest from the chroot's suite, as on a fresh machine.
set -euo pipefail
MIRROR=${MIRROR:-http://deb.debian.org/debian}

usage() {
  sed -n '3,7p' "$0" >&2
  exit 2
}

mounted() { mountpoint -q "$1"; }

mount_all() {
  local dir=$1
  mounted "$dir/proc" || mount -t proc proc "$dir/proc"
  mounted "$dir/sys" || mount -t sysfs sysfs "$dir/sys"
  mounted "$dir/dev" || mount --bind /dev "$dir/dev"
  mounted "$dir/dev/pts" || mount --bind /dev/pts "$dir/dev/pts"
  # Name resolution, and the host's CA bundle for pip and apt's https (it holds a proxy's CA where the host has one;
  # the chroot's own ca-certificates package would replace a copy at the usual path).
  cp -L /etc/resolv.conf "$dir/etc/resolv.conf"
  mkdir -p "$dir/etc/ssl/certs"
  cp -L /etc/ssl/certs/ca-certificates.crt "$dir/etc/ssl/host-ca-certificates.crt"
}

umount_all() {
  local dir=$1 point
  for point in dev/pts dev sys proc; do
    if mounted "$dir/$point"; then umount "$dir/$point"; fi
  done
}

in_chroot() {
  local dir=$1
  shift
  mount_all "$dir"
  chroot "$dir" /usr/bin/env -i HOME=/root TERM="${TERM:-dumb}" LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin DEBIAN_FRONTEND=noninteractive \
    PIP_CERT=/etc/ssl/host-ca-certificates.crt SSL_CERT_FILE=/etc/ssl/host-ca-certificates.crt "$@"
}

create() {
  local dir=$1 suite=$2 base=$2
  [ "$suite" = trixie-backports ] && base=trixie
  if [ ! -x "$dir/usr/bin/apt-get" ]; then
    mkdir -p "$dir"
    debootstrap --variant=minbase "$base" "$dir" "$MIRROR"
  fi
  # Signatures are still checked; the date check is off because a snapshot mirror's Release file expires.
  echo 'Acquire::Check-Valid-Until "false";' >"$dir/etc/apt/apt.conf.d/99no-check-valid-until"
  if [ "$suite" = trixie-backports ]; then
    echo "deb $MIRROR trixie-backports main" >"$dir/etc/apt/sources.list.d/backports.list"
    # Backports win for every package they have, so `make setup` installs QGIS 3.44 and what it needs with it.
    printf 'Package: *\nPin: release n=trixie-backports\nPin-Priority: 500\n' >"$dir/etc/apt/preferences.d/backports"
  fi
  in_chroot "$dir" apt-get update -q
  in_chroot "$dir" apt-get install -y -q --no-install-recommends make git ca-certificates
}

[ $# -ge 2 ] || usage
command=$1
dir=$(realpath -m "$2")
shift 2
case $command in
  create)
    [ $# -eq 1 ] || usage
    create "$dir" "$1"
    ;;
  enter)
    if [ $# -eq 0 ]; then set -- bash -l; fi
    in_chroot "$dir" "$@"
    ;;
  test)
    target=${1:-}
    repo=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
    rm -rf "$dir/root/incircu"
    git clone --quiet "$repo" "$dir/root/incircu"
    git -C "$dir/root/incircu" checkout --quiet "$(git -C "$repo" rev-parse HEAD)"
    if [ -z "$target" ]; then
      in_chroot "$dir" bash -c 'cd /root/incircu && .ci/run'
    else
      in_chroot "$dir" make -C /root/incircu "$target"
    fi
    ;;
  umount) umount_all "$dir" ;;
  *) usage ;;
esac
