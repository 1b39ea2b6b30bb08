#!/usr/bin/env python3
"""Builds the Unity package (UPM) a Unity developer installs: `Add package from tarball` takes the .tgz.

Usage: package-unity.py SOURCE_DIR BUILD_DIR OUT_DIR

OUT_DIR/com.octocap.avatar/ and OUT_DIR/com.octocap.avatar-VERSION.tgz (files under package/, as npm packs them):
  package.json, README.md, LICENSE.md, NOTICE.md
  Runtime/                 the Unity components and their asmdef
  Runtime/Plugins/Octocap.dll          the managed bindings (compiled here with mcs, C# 7.2 as Unity takes it)
  Runtime/Plugins/x86_64/liboctocap.so the native library, with the libraries Debian does not ship beside it
                                       (ONNX Runtime, OpenVINO: liboctocap finds them through its $ORIGIN RUNPATH)
  Runtime/Plugins/x86_64/models/       the pose models, where liboctocap looks first (beside itself)
Every file and folder has a .meta: Unity ignores a package file without one when the package is immutable (a
tarball, a git URL). GUIDs are derived from the file's path in the package, so a rebuilt package keeps them and a
project's references survive an update. Native plugins are marked for the Linux x86_64 editor and player only.
"""
import hashlib, os, re, shutil, subprocess, sys, tarfile

sys.dont_write_bytecode = True  # importing the module below leaves no scripts/__pycache__ in the source tree
from header_version import header_version  # scripts/header_version.py, beside this file

NAME = "com.octocap.avatar"


def guid(rel):
    return hashlib.md5((NAME + "/" + rel).encode()).hexdigest()


def common_tail():
    return "  userData: \n  assetBundleName: \n  assetBundleVariant: \n"


def meta_for(rel, is_dir):
    head = "fileFormatVersion: 2\nguid: %s\n" % guid(rel)
    if is_dir:
        return head + "folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n" + common_tail()
    if rel.endswith(".cs"):
        return head + ("MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n"
                       "  executionOrder: 0\n  icon: {instanceID: 0}\n") + common_tail()
    if rel.endswith(".asmdef"):
        return head + "AssemblyDefinitionImporter:\n  externalObjects: {}\n" + common_tail()
    if re.search(r"\.(md|json|txt)$", rel):
        return head + "TextScriptImporter:\n  externalObjects: {}\n" + common_tail()
    if rel.endswith("Octocap.dll"):  # managed: every platform
        return head + plugin_importer(native=False) + common_tail()
    if rel.endswith(".so"):
        return head + plugin_importer(native=True) + common_tail()
    return head + "DefaultImporter:\n  externalObjects: {}\n" + common_tail()


def plugin_importer(native):
    if not native:
        platforms = ("  - first:\n      Any: \n    second:\n      enabled: 1\n      settings: {}\n")
    else:
        # The Linux x86_64 editor and player; every other target excluded (no library for it in this package).
        platforms = ("  - first:\n      : Any\n    second:\n      enabled: 0\n      settings:\n"
                     "        Exclude Editor: 0\n        Exclude Linux64: 0\n        Exclude OSXUniversal: 1\n"
                     "        Exclude Win: 1\n        Exclude Win64: 1\n"
                     "  - first:\n      Any: \n    second:\n      enabled: 0\n      settings: {}\n"
                     "  - first:\n      Editor: Editor\n    second:\n      enabled: 1\n      settings:\n"
                     "        CPU: x86_64\n        DefaultValueInitialized: true\n        OS: Linux\n"
                     "  - first:\n      Standalone: Linux64\n    second:\n      enabled: 1\n      settings:\n"
                     "        CPU: x86_64\n"
                     "  - first:\n      Standalone: Win64\n    second:\n      enabled: 0\n      settings:\n"
                     "        CPU: None\n"
                     "  - first:\n      Standalone: OSXUniversal\n    second:\n      enabled: 0\n      settings:\n"
                     "        CPU: None\n")
    return ("PluginImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  iconMap: {}\n  executionOrder: {}\n"
            "  defineConstraints: []\n  isPreloaded: 0\n  isOverridable: 0\n  isExplicitlyReferenced: 0\n"
            "  validateReferences: 1\n  platformData:\n" + platforms)


def soname(lib):
    out = subprocess.run(["readelf", "-d", lib], check=True, capture_output=True, text=True).stdout
    m = re.search(r"\(SONAME\)\s+Library soname: \[([^\]]+)\]", out)
    return m.group(1) if m else None


def main():
    src, build, out = (os.path.abspath(a) for a in sys.argv[1:4])
    version = header_version(src)
    unity = os.path.join(src, "bindings/csharp/Unity")
    pkg = os.path.join(out, NAME)
    shutil.rmtree(pkg, ignore_errors=True)
    shutil.copytree(unity, pkg, ignore=shutil.ignore_patterns("*.meta"))
    shutil.copy(os.path.join(src, "NOTICE"), os.path.join(pkg, "NOTICE.md"))
    plugins = os.path.join(pkg, "Runtime/Plugins")
    os.remove(os.path.join(plugins, "README.md"))  # says how to fill the folder by hand; here it is filled
    subprocess.run(["mcs", "-langversion:7.2", "-unsafe", "-warnaserror", "-target:library",
                    "-out:" + os.path.join(plugins, "Octocap.dll"),
                    "-recurse:" + os.path.join(src, "bindings/csharp/Octocap/*.cs")], check=True)
    native = os.path.join(plugins, "x86_64")
    os.makedirs(native)
    # From an install of the build: there the library's RUNPATH is $ORIGIN and lib/ holds what Debian does not ship
    # (ONNX Runtime, OpenVINO and the plugins OpenVINO loads by name), so the folder works wherever it lands.
    stage = os.path.join(out, "stage")
    shutil.rmtree(stage, ignore_errors=True)
    subprocess.run(["cmake", "--install", build, "--prefix", stage], check=True, stdout=subprocess.DEVNULL)
    libdir = os.path.join(stage, "lib")
    lib = os.path.realpath(os.path.join(libdir, "liboctocap.so"))
    # DllImport("octocap") asks for liboctocap.so; one file under that name (Unity imports files, not links).
    shutil.copy(lib, os.path.join(native, "liboctocap.so"))
    carried = []
    for f in sorted(os.listdir(libdir)):
        full = os.path.join(libdir, f)
        if f.startswith("liboctocap") or os.path.islink(full) or not re.match(r"lib.*\.so(\.[\d.]+)?$", f):
            continue
        # Each file once, under the name the loader asks for: its soname (libonnxruntime.so.1), or its own name for
        # a plugin OpenVINO opens by path (libopenvino_intel_cpu_plugin.so has none).
        name = soname(full) or f
        shutil.copy(full, os.path.join(native, name))
        carried.append(name)
    shutil.copytree(os.path.join(stage, "share/octocap/models"), os.path.join(native, "models"))
    shutil.rmtree(stage)
    for root, dirs, files in os.walk(pkg):
        for name in dirs + files:
            full = os.path.join(root, name)
            rel = os.path.relpath(full, pkg)
            with open(full + ".meta", "w") as f:
                f.write(meta_for(rel, os.path.isdir(full)))
    tgz = os.path.join(out, "%s-%s.tgz" % (NAME, version))
    with tarfile.open(tgz, "w:gz", compresslevel=1) as t:  # models and libraries hardly compress
        t.add(pkg, arcname="package")
    print("unity package %s %s: %s (%d native libraries carried: %s)" %
          (NAME, version, tgz, len(carried), ", ".join(carried) or "none"))


if __name__ == "__main__":
    main()
