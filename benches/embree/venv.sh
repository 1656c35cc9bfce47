# Sourced by compare.sh and native.sh: the virtual environment under target/
# that holds embreex (Embree's Python binding, whose wheel carries Embree 4's
# library) and numpy, made with pip if it is missing. Expects root, the
# repository's folder; sets venv, its path.
venv="$root/target/embree-venv"
if [[ ! -x $venv/bin/python ]] || ! "$venv/bin/python" -c "import embreex, numpy" 2>/dev/null; then
    echo "installing embreex and numpy into $venv" >&2
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --upgrade pip >&2
    "$venv/bin/pip" install --quiet "embreex>=4.3" numpy >&2
fi
