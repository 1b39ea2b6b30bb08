#!/usr/bin/env python3
"""Builds the Unity package with scripts/package-unity.py and checks it against what Unity documents for an
immutable package (a tarball or git URL install), since no Unity editor runs here.

Usage: check_unity_package.py SOURCE_DIR BUILD_DIR PROBE WORK_DIR
"""
import json, os, re, shutil, subprocess, sys, tarfile

src, build, probe, work = (os.path.abspath(a) for a in sys.argv[1:5])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
subprocess.run([sys.executable, os.path.join(src, "scripts/package-unity.py"), src, build, work], check=True)
pkg = os.path.join(work, "com.octocap.avatar")
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


sys.path.insert(0, os.path.join(src, "scripts"))
sys.dont_write_bytecode = True  # no scripts/__pycache__ in the source tree
from header_version import header_version  # scripts/header_version.py: the header's version, one reader for all

version = header_version(src)

# The manifest: the fields UPM requires, the header's version, an SPDX licence.
manifest = json.load(open(os.path.join(pkg, "package.json")))
if not re.fullmatch(r"[a-z0-9-]+(\.[a-z0-9-]+){2,}", manifest.get("name", "")):
    fail("package.json name %r is not reverse-domain lower case" % manifest.get("name"))
if manifest.get("version") != version:
    fail("package.json version %r, the header says %s" % (manifest.get("version"), version))
if manifest.get("license") != "Apache-2.0":
    fail("package.json license is not Apache-2.0")
if not re.fullmatch(r"\d{4}\.\d", manifest.get("unity", "")):
    fail("package.json unity %r is not YEAR.MINOR" % manifest.get("unity"))
if open(os.path.join(pkg, "LICENSE.md")).read() != open(os.path.join(src, "LICENSE")).read():
    fail("LICENSE.md is not the repository's LICENSE")

# Every asset has a .meta, every .meta an asset, and GUIDs are unique: Unity ignores an unmetaed file in an
# immutable package, and two equal GUIDs break every reference to either.
guids = {}
metas = 0
for root, dirs, files in os.walk(pkg):
    for name in dirs + files:
        full = os.path.join(root, name)
        rel = os.path.relpath(full, pkg)
        if name.endswith(".meta"):
            if not os.path.exists(full[:-5]):
                fail("%s has no asset" % rel)
            continue
        meta = full + ".meta"
        if not os.path.exists(meta):
            fail("%s has no .meta" % rel)
            continue
        metas += 1
        text = open(meta).read()
        m = re.search(r"^guid: ([0-9a-f]{32})$", text, re.M)
        if not text.startswith("fileFormatVersion: 2\n") or not m:
            fail("%s.meta: no fileFormatVersion 2 and 32-hex guid" % rel)
            continue
        if m.group(1) in guids:
            fail("%s and %s share guid %s" % (rel, guids[m.group(1)], m.group(1)))
        guids[m.group(1)] = rel
        if os.path.isdir(full) and "folderAsset: yes" not in text:
            fail("%s.meta: a folder without folderAsset: yes" % rel)
        if rel.endswith(".cs") and "MonoImporter:" not in text:
            fail("%s.meta: a script without MonoImporter" % rel)
        if rel.endswith(".asmdef") and "AssemblyDefinitionImporter:" not in text:
            fail("%s.meta: an asmdef without AssemblyDefinitionImporter" % rel)

# The plugins: the managed bindings for every platform, the native library for the Linux x86_64 editor and player.
plugins = os.path.join(pkg, "Runtime/Plugins")
managed = open(os.path.join(plugins, "Octocap.dll.meta")).read()
if "PluginImporter:" not in managed or not re.search(r"Any: \n    second:\n      enabled: 1", managed):
    fail("Octocap.dll.meta does not enable the managed plugin on any platform")
native = open(os.path.join(plugins, "x86_64/liboctocap.so.meta")).read()
for want in (r"Standalone: Linux64\n    second:\n      enabled: 1", r"Editor: Editor\n    second:\n      enabled: 1",
             r"OS: Linux", r"Standalone: Win64\n    second:\n      enabled: 0", r"Exclude Win64: 1"):
    if not re.search(want, native):
        fail("liboctocap.so.meta lacks %r" % want)
asmdef = json.load(open(os.path.join(pkg, "Runtime/Octocap.Unity.asmdef")))
for ref in asmdef.get("precompiledReferences", []):
    if not os.path.exists(os.path.join(plugins, ref)):
        fail("the asmdef references %s, which the package does not carry" % ref)

# The native folder stands alone: what the library loads resolves inside it, and the models it finds are its own.
lib = os.path.join(plugins, "x86_64/liboctocap.so")
ldd = subprocess.run(["ldd", lib], capture_output=True, text=True).stdout
for line in ldd.splitlines():
    if "not found" in line:
        fail("the packaged library: " + line.strip())
    if re.search(r"lib(onnxruntime|openvino)", line) and os.path.dirname(lib) not in line:
        fail("the packaged library loads %s from outside the package" % line.strip())
copy = os.path.join(work, "moved/Plugins/x86_64")  # moved, as a project moves a package: nothing may be absolute
shutil.copytree(os.path.join(plugins, "x86_64"), copy)
env = dict(os.environ)
env.pop("OCTOCAP_MODELS_DIR", None)
env.pop("LD_LIBRARY_PATH", None)
ok = subprocess.run([probe, os.path.join(copy, "liboctocap.so"), "movenet-thunder"], capture_output=True, text=True, env=env)
if ok.stdout.strip() != "ok":
    fail("the moved package's library did not load movenet-thunder: " + ok.stdout.strip() + ok.stderr.strip())
os.remove(os.path.join(copy, "models/movenet-lightning.onnx"))
gone = subprocess.run([probe, os.path.join(copy, "liboctocap.so"), "movenet-lightning"], capture_output=True, text=True, env=env)
if gone.returncode == 0 or os.path.join(copy, "models") not in gone.stdout:
    fail("with a model removed from the package, the library did not look for it beside itself: " + gone.stdout.strip())

# The tarball UPM installs: the package under package/, as npm packs it.
tgz = os.path.join(work, "com.octocap.avatar-%s.tgz" % version)
with tarfile.open(tgz) as t:
    names = t.getnames()
if "package/package.json" not in names or any(not n.startswith("package") for n in names):
    fail("%s does not hold the package under package/" % os.path.basename(tgz))

if failures:
    sys.exit(1)
print("unity package %s: %d assets with unique GUIDs, plugins for Linux x86_64, library and models self-contained, "
      "tarball under package/" % (version, metas))
