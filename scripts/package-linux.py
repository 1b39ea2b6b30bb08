#!/usr/bin/env python3
"""Builds the portable Linux release: a folder that runs on a Linux that has none of octocap's dependencies.

Usage: package-linux.py SOURCE_DIR BUILD_DIR OUT_DIR [--tar]

OUT_DIR/octocap-VERSION-linux-x86_64/ (and, with --tar, OUT_DIR/octocap-VERSION-linux-x86_64.tar.gz):
  bin/        octocap, octocap-calibrate, octocap-stream-echo (RUNPATH $ORIGIN/../lib); not the viewer (below)
  lib/        liboctocap.so.0 and every library it and the tools load that is not the system's own, each under the
              name the loader asks for, each with RUNPATH $ORIGIN (a library's RUNPATH serves only its own
              dependencies, so every carried library needs one for the libraries it needs in turn)
  include/, lib/cmake/, lib/pkgconfig/   as `cmake --install` puts them (pkg-config and find_package work from here)
  share/octocap/models/    the pose models, where the library looks from lib/ (../share/octocap/models)
  share/octocap/sample/    the built-in sample recording (README.txt says how to solve it)
  share/doc/octocap/       LICENSE, NOTICE, and third-party/<package>.copyright for every Debian package whose
                           library is carried (their licences travel with their code), listed in CARRIED.txt
  README.txt               what this is, what it needs from the system, the first command

The system's own libraries are the ones every Linux has: the C library (glibc: libc, libm, libpthread, libdl, librt,
libresolv, the loader) and the compiler's runtime (libgcc_s, libstdc++). That is auditwheel's manylinux policy less
X11, GLib and OpenGL, which a server or a container does not have. Debian's OpenCV core links OpenGL (octocap never
calls it), so GLVND's dispatch libraries (libGL, libGLX, libGLdispatch) are carried: they hold no driver, and in a
process that already has the system's (an engine's editor) the loader uses those, matched by soname. The release's floor is the newest glibc symbol version its
files use, printed and written to README.txt.
"""
import os, re, shutil, subprocess, sys, tarfile

sys.dont_write_bytecode = True  # importing the module below leaves no scripts/__pycache__ in the source tree
from header_version import header_version  # scripts/header_version.py, beside this file

SYSTEM = re.compile(r"^(ld-linux-x86-64\.so\.2|libc\.so\.6|libm\.so\.6|libpthread\.so\.0|libdl\.so\.2|librt\.so\.1|"
                    r"libresolv\.so\.2|libutil\.so\.1|libnsl\.so\.1|libmvec\.so\.1|libgcc_s\.so\.1|libstdc\+\+\.so\.6|"
                    r"linux-vdso\.so\.1)$")


def run(*cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def is_elf(path):
    if os.path.islink(path) or not os.path.isfile(path):
        return False
    with open(path, "rb") as f:
        return f.read(4) == b"\x7fELF"


def elf_files(*dirs):
    return [os.path.join(d, f) for d in dirs for f in sorted(os.listdir(d)) if is_elf(os.path.join(d, f))]


def needed(path):
    """(name, resolved path) of everything the loader maps for path, as ldd resolves it; 'not found' is an error."""
    out = run("ldd", path)
    deps = []
    for line in out.splitlines():
        m = re.match(r"\s*(\S+) => (.*?)(?: \(0x[0-9a-f]+\))?$", line)
        if not m:
            continue
        name, where = m.group(1), m.group(2).strip()
        if where == "not found":
            sys.exit("package-linux: %s needs %s, which this machine does not have" % (path, name))
        deps.append((name, where))
    return deps


def debian_package(path):
    """The Debian package that owns path (its /usr-merged twin too), or None."""
    for candidate in (path, re.sub(r"^/usr/lib/", "/lib/", path), re.sub(r"^/lib/", "/usr/lib/", path)):
        r = subprocess.run(["dpkg-query", "-S", candidate], capture_output=True, text=True)
        if r.returncode == 0 and r.stdout:
            return r.stdout.split(":")[0].strip()
    return None


def glibc_floor(files):
    newest = (0, 0)
    for f in files:
        for m in re.finditer(r"GLIBC_(\d+)\.(\d+)", run("objdump", "-T", f)):
            newest = max(newest, (int(m.group(1)), int(m.group(2))))
    return "%d.%d" % newest


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) != 3:
        sys.exit(__doc__)
    src, build, out = (os.path.abspath(a) for a in args)
    version = header_version(src)
    name = "octocap-%s-linux-x86_64" % version
    root = os.path.join(out, name)
    shutil.rmtree(root, ignore_errors=True)
    subprocess.run(["cmake", "--install", build, "--prefix", root], check=True, stdout=subprocess.DEVNULL)
    lib = os.path.join(root, "lib")
    bindir = os.path.join(root, "bin")
    # The viewer is a sample of skinning, not a tool of the release: its OSMesa would carry LLVM and Z3 (150 MB, a
    # fifth of the release) for a headless render that the engines do themselves.
    os.remove(os.path.join(bindir, "octocap-viewer"))
    for tool in sorted(os.listdir(bindir)):
        rp = run("readelf", "-d", os.path.join(bindir, tool))
        if "$ORIGIN/../lib" not in rp:
            sys.exit("package-linux: bin/%s has no RUNPATH $ORIGIN/../lib (tools/ CMake sets it)" % tool)

    # Carry every library the loader maps that is not the system's, until nothing new appears (a carried library's
    # own needs are resolved on this machine, then carried too).
    carried = {}  # name -> (source path, Debian package)
    todo = elf_files(bindir, lib)
    seen = set()
    while todo:
        elf = todo.pop()
        if elf in seen:
            continue
        seen.add(elf)
        for dep, where in needed(elf):
            if SYSTEM.match(dep) or dep in carried or os.path.exists(os.path.join(lib, dep)):
                continue
            real = os.path.realpath(where)
            dest = os.path.join(lib, dep)
            shutil.copy(real, dest)
            os.chmod(dest, 0o755)
            carried[dep] = (real, debian_package(real))
            todo.append(dest)
    for dep in carried:
        subprocess.run(["patchelf", "--set-rpath", "$ORIGIN", os.path.join(lib, dep)], check=True)
    # Libraries that install already put beside liboctocap (ONNX Runtime, OpenVINO and its plugins) keep theirs.

    docs = os.path.join(root, "share/doc/octocap")
    third = os.path.join(docs, "third-party")
    os.makedirs(third, exist_ok=True)
    packages = sorted({p for _, p in carried.values() if p})
    for p in packages:
        copyright = "/usr/share/doc/%s/copyright" % p
        if not os.path.exists(copyright):
            sys.exit("package-linux: %s carries a library of %s, whose copyright file is missing" % (name, p))
        shutil.copy(copyright, os.path.join(third, p + ".copyright"))
    with open(os.path.join(docs, "CARRIED.txt"), "w") as f:
        f.write("Libraries carried in lib/, with the Debian package each comes from (its licence is\n"
                "third-party/<package>.copyright); ONNX Runtime and OpenVINO come from their PyPI wheels (NOTICE).\n\n")
        for dep in sorted(carried):
            f.write("%s\t%s\n" % (dep, carried[dep][1] or "(not a Debian package)"))

    shutil.copytree(os.path.join(src, "data/sample"), os.path.join(root, "share/octocap/sample"))
    floor = glibc_floor(elf_files(bindir, lib))
    with open(os.path.join(root, "README.txt"), "w") as f:
        f.write("""octocap {v}, portable Linux x86_64 release

Unpack anywhere and run; nothing needs installing. The tools find lib/ beside them, the library finds its models
in share/octocap/models (or $OCTOCAP_MODELS_DIR).

From the system it needs only glibc {floor} or newer and libstdc++ of GCC 12 or newer. Every other library is in lib/ ({n} carried, listed in share/doc/octocap/CARRIED.txt
with their licences beside it).

The built-in sample recording, solved into 3D:
  bin/octocap solve --calibration share/octocap/sample/calibration.toml \\
      --keypoints share/octocap/sample/keypoints --output sample.trc \\
      --ground-truth share/octocap/sample/ground_truth.csv --rate 30

A program in C: cc app.c -Iinclude -Llib -loctocap -Wl,-rpath,'$ORIGIN/lib' (or pkg-config / find_package with
this folder as the prefix). The reference is include/octocap/octocap.h.
""".format(v=version, floor=floor, n=len(carried)))
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(root) for f in fs
               if not os.path.islink(os.path.join(d, f)))
    print("linux release %s: %s, %d libraries carried from %d Debian packages, glibc >= %s, %.0f MB"
          % (version, root, len(carried), len(packages), floor, size / 1e6))
    if "--tar" in sys.argv[1:]:
        tgz = root + ".tar.gz"
        with tarfile.open(tgz, "w:gz", compresslevel=1) as t:
            t.add(root, arcname=name)
        print("  %s" % tgz)


if __name__ == "__main__":
    main()
