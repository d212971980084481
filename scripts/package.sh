#!/usr/bin/env bash
# Packs the built add-on (blender_addon/footfall, with the compiled module that
# scripts/build.sh puts there) into two zips in the folder given (default dist/):
#   footfall-VERSION-addon.zip      the legacy add-on, the folder footfall/ inside
#                                   (Blender 3.4 and later: Preferences > Add-ons > Install)
#   footfall-VERSION-extension.zip  the extension, its blender_manifest.toml at the root
#                                   (Blender 4.2 and later: Get Extensions > Install from Disk)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-dist}
addon=blender_addon/footfall
if ! compgen -G "$addon/_native*.so" >/dev/null; then
  echo "package.sh: $addon has no compiled module; run scripts/build.sh first" >&2
  exit 2
fi
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' "$addon/blender_manifest.toml")
mkdir -p "$out"
/usr/bin/python3 - "$addon" "$out" "$version" <<'PY'
import pathlib, sys, zipfile

addon, out, version = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), sys.argv[3]
files = sorted(p for p in addon.rglob("*") if p.is_file() and "__pycache__" not in p.parts and p.suffix != ".pyc")
for kind, prefix in (("addon", "footfall/"), ("extension", "")):
    target = out / f"footfall-{version}-{kind}.zip"
    partial = target.with_suffix(".zip.partial")
    with zipfile.ZipFile(partial, "w", zipfile.ZIP_DEFLATED) as archive:
        for path in files:
            archive.write(path, prefix + path.relative_to(addon).as_posix())
    partial.replace(target)
    print(target)
PY
