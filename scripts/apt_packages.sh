# Shared by scripts/bootstrap.sh and scripts/fuzz.sh.
# Usage: source scripts/apt_packages.sh; install_debian_packages LOG_NAME PACKAGE...
# Installs the Debian packages not yet installed (apt-get, with sudo when not
# root); logs through `log` with "LOG_NAME present" when nothing is missing.
install_debian_packages() {
    local present_text=$1
    shift
    local sudo="" missing=() p
    if [ "$(id -u)" != 0 ]; then sudo="sudo"; fi
    for p in "$@"; do
        if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$p")
        fi
    done
    if [ "${#missing[@]}" -gt 0 ]; then
        log "installing Debian packages: ${missing[*]}"
        $sudo apt-get update -qq >&2
        DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
    else
        log "$present_text present"
    fi
}
