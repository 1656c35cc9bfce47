# Sourced by the POV-Ray comparisons (povray/compare.sh, spd/compare.sh):
# installs POV-Ray from the system's package manager (apt-get) if it is
# missing, sets povray_version, and builds raytree's release binary, setting
# raytree to its path. Expects root, the repository's folder.
if ! command -v povray >/dev/null; then
    echo "POV-Ray is missing: installing it with apt-get" >&2
    sudo=""
    [[ $(id -u) -eq 0 ]] || sudo=sudo
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq povray >/dev/null
fi
povray_version=$(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.]*[^ ]*' || true)

cargo build --release --quiet --manifest-path "$root/Cargo.toml"
raytree="$root/target/release/raytree"
