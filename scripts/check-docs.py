#!/usr/bin/env python3
"""Checks README.md and docs/*.md against the repository and the built command line.

Usage: check-docs.py SOURCE_DIR OCTOCAP_BINARY

(a) Every relative markdown link resolves: to an existing file or folder of the repository, and a #anchor to a
    heading of the linked markdown file (GitHub's anchors: the heading's text in lower case, punctuation dropped,
    spaces made hyphens, "-1", "-2" ... for repeats).
(b) Every `octocap SUBCOMMAND ...` in a ```bash or ```sh block (however the binary is named there:
    `octocap`, `build/tools/octocap/octocap`, `./octocap`, "$BUILD_DIR/tools/octocap/octocap") names a subcommand
    that `OCTOCAP_BINARY --help` lists, and every --long-flag it uses is listed by `OCTOCAP_BINARY SUBCOMMAND --help`.
    A command runs on over lines ending in a backslash and over synopsis lines that start with `[-`, `[.` or `--`,
    and ends at `;`, `&` or `|` outside brackets, or at its `#` comment; an invocation inside a synopsis' brackets,
    "[detector options as for octocap solve --images]", ends where they close and owns the flags inside them.

Prints `FAIL: FILE:LINE: ...` for each problem and exits 1, else prints one line saying what was checked.
Standard library only.
"""
import glob
import os
import re
import subprocess
import sys
import urllib.parse

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})\s*([\w+-]*)")
HEADING = re.compile(r"^ {0,3}(#{1,6})[ \t]+(.*?)[ \t]*#*[ \t]*$")
# [text](target) and ![alt](target); target optionally <...>, optionally followed by a "title".
INLINE_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*(<[^>]*>|[^\s()]*(?:\([^\s()]*\)[^\s()]*)*)(?:\s+(?:\"[^\"]*\"|'[^']*'|\([^)]*\)))?\s*\)")
REFERENCE_DEF = re.compile(r"^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)")
HTML_ID = re.compile(r"<a\s[^>]*(?:name|id)\s*=\s*[\"']([^\"']+)[\"']", re.I)
SHELL_LANGS = {"bash", "sh", "shell"}
# The binary: a word whose last path component is `octocap`, then the subcommand (or a top-level option).
INVOCATION = re.compile(r"(?:^|(?<=[\s;&|(`'\"]))[\"']?(?:[^\s\"';&|()`]*/)?octocap[\"']?[ \t]+(?P<sub>[^\s;&|()\[\]\"'`]+)")
FLAG = re.compile(r"(?:^|(?<=[\s\[(|]))(--[A-Za-z0-9][A-Za-z0-9_-]*)")
HELP_OPTION = re.compile(r"^ {1,4}(-[^\s]+)")


def github_slug(text):
    """The anchor GitHub gives a heading whose markdown text is `text`."""
    text = re.sub(r"!\[([^\]]*)\]\([^)]*\)", r"\1", text)        # images: their alt text
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)         # links: their text
    text = re.sub(r"<[^>]+>", "", text)                          # inline HTML
    text = text.replace("`", "").replace("*", "")
    text = re.sub(r"(^|\s)_+|_+(\s|$)", r"\1\2", text)           # _emphasis_ (underscores inside words stay)
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)                         # \w: letters, digits, underscore (Unicode)
    return text.replace(" ", "-")


class Markdown:
    """A markdown file read once: its lines, which of them are in fenced code (and which fence language), its anchors."""

    def __init__(self, path):
        self.path = path
        with open(path, encoding="utf-8") as f:
            self.lines = f.read().split("\n")
        self.code_lang = [None] * len(self.lines)   # None outside fences; the fence's language (maybe "") inside
        self.anchors = set()
        fence, lang, counts = None, None, {}
        for i, line in enumerate(self.lines):
            m = FENCE.match(line)
            if fence is None and m:
                fence, lang = m.group(1), m.group(2).lower()
                self.code_lang[i] = ""            # the opening fence line itself is not code to check
                continue
            if fence is not None:
                if line.strip().startswith(fence[0] * len(fence)) and line.strip().strip(fence[0]) == "":
                    fence, lang = None, None
                    self.code_lang[i] = ""
                else:
                    self.code_lang[i] = lang
                continue
            h = HEADING.match(line)
            if h:
                slug = github_slug(h.group(2))
                n = counts.get(slug, 0)
                counts[slug] = n + 1
                self.anchors.add(slug if n == 0 else "%s-%d" % (slug, n))
            for a in HTML_ID.findall(line):
                self.anchors.add(a)


def strip_code_spans(line):
    """The line with `inline code` blanked (same length, so columns stay)."""
    return re.sub(r"(`+)(.+?)\1", lambda m: " " * len(m.group(0)), line)


def check_links(doc, root, docs_cache, rel, failures):
    checked = 0
    for i, line in enumerate(doc.lines):
        if doc.code_lang[i] is not None:
            continue
        text = strip_code_spans(line)
        targets = [m.group(1) for m in INLINE_LINK.finditer(text)]
        m = REFERENCE_DEF.match(text)
        if m:
            targets.append(m.group(1))
        for target in targets:
            target = target.strip()
            if target.startswith("<") and target.endswith(">"):
                target = target[1:-1]
            if not target or re.match(r"^[A-Za-z][A-Za-z0-9+.-]*:", target) or target.startswith("//"):
                continue                      # http:, https:, mailto: ...: not ours to check
            checked += 1
            path_part, _, anchor = target.partition("#")
            path_part = urllib.parse.unquote(path_part)
            if path_part == "":
                dest = doc.path
            elif path_part.startswith("/"):
                dest = os.path.normpath(os.path.join(root, path_part.lstrip("/")))
            else:
                dest = os.path.normpath(os.path.join(os.path.dirname(doc.path), path_part))
            where = "%s:%d" % (rel(doc.path), i + 1)
            if not os.path.exists(dest):
                failures.append("FAIL: %s: link %s: %s does not exist" % (where, target, rel(dest)))
                continue
            if os.path.commonpath([os.path.realpath(dest), os.path.realpath(root)]) != os.path.realpath(root):
                failures.append("FAIL: %s: link %s leaves the repository" % (where, target))
                continue
            if anchor and dest.endswith(".md") and os.path.isfile(dest):
                if dest not in docs_cache:
                    docs_cache[dest] = Markdown(dest)
                if urllib.parse.unquote(anchor) not in docs_cache[dest].anchors:
                    failures.append("FAIL: %s: link %s: no heading #%s in %s" % (where, target, anchor, rel(dest)))
    return checked


def blank_quoted(text):
    """Quoted strings blanked (same length), so that nothing inside them is taken for a flag or a separator."""
    out, quote = [], None
    for ch in text:
        if quote:
            out.append(" " if ch != quote else ch)
            if ch == quote:
                quote = None
        else:
            if ch in "'\"":
                quote = ch
            out.append(ch)
    return "".join(out)


def strip_comment(text):
    """A shell line without its # comment (a # that starts a word, outside quotes)."""
    quote = None
    for j, ch in enumerate(text):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "#" and (j == 0 or text[j - 1] in " \t"):
            return text[:j]
    return text


def logical_commands(doc):
    """The shell blocks' commands: (text, [(offset in text, line number)]) with continuation lines joined."""
    commands, current = [], None
    for i, line in enumerate(doc.lines):
        lang = doc.code_lang[i]
        if lang is None or lang not in SHELL_LANGS:
            if current:
                commands.append(current)
                current = None
            continue
        code = strip_comment(line)
        stripped = code.strip()
        if current and (current[2] or stripped.startswith(("[-", "[.", "--"))):
            text, starts, _ = current
            starts.append((len(text) + 1, i + 1))
            text += " " + code
        else:
            if current:
                commands.append(current)
            text, starts = code, [(0, i + 1)]
        continues = text.rstrip().endswith("\\")
        if continues:
            text = text.rstrip()[:-1]
        current = (text, starts, continues)
    if current:
        commands.append(current)
    return [(t, s) for t, s, _ in commands]


def line_at(starts, offset):
    number = starts[0][1]
    for start, n in starts:
        if start <= offset:
            number = n
    return number


def bracket_depths(scan):
    """For each position of a (quote-blanked) command, how many [...] and (...) groups enclose it."""
    depths, depth = [], 0
    for ch in scan:
        if ch in "])":
            depth = max(0, depth - 1)
        depths.append(depth)
        if ch in "[(":
            depth += 1
    return depths


def command_end(scan, depths, start):
    """Where the command whose words start at `start` ends: where its bracket group closes (an invocation inside
    `[...]` or `(...)` of a synopsis: "(then octocap solve --sync FILE)"), or, outside brackets, at ;, & or |."""
    level = depths[start] if start < len(depths) else 0
    for j in range(start, len(scan)):
        if depths[j] < level:
            return j
        if level == 0 and depths[j] == 0 and scan[j] in ";&|":
            return j
    return len(scan)


def help_options(binary, args, cache):
    key = tuple(args)
    if key not in cache:
        try:
            out = subprocess.run([binary] + args + ["--help"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 timeout=30, universal_newlines=True)
            text, ok = out.stdout, out.returncode == 0
        except (OSError, subprocess.TimeoutExpired) as e:
            text, ok = str(e), False
        options, subcommands, section = set(), set(), None
        for line in text.split("\n"):
            if re.match(r"^\S.*:\s*$", line):
                section = line.strip().rstrip(":").lower()
                continue
            m = HELP_OPTION.match(line)
            if m and section != "subcommands":
                for name in m.group(1).split(","):
                    options.add(re.split(r"[={]", name)[0])  # CLI11: --opt=DEFAULT, --flag{false} (a negation's default)
            elif section == "subcommands":
                s = re.match(r"^ {1,4}(\S+)", line)
                if s:
                    subcommands.add(s.group(1))
        cache[key] = (ok, options, subcommands, text)
    return cache[key]


def check_commands(doc, binary, cache, rel, failures):
    commands = flags = 0
    top_ok, top_options, subcommands, top_text = help_options(binary, [], cache)
    for text, starts in logical_commands(doc):
        scan = blank_quoted(text)
        depths = bracket_depths(scan)
        # Invocations are looked for in the text as written (quotes around the binary's own path, as in
        # "$BUILD_DIR/tools/octocap/octocap", are fine), but one whose subcommand is inside a quoted string is text
        # for another program (echo "..."), not a command. Flags are read with quoted strings blanked.
        invocations = [m for m in INVOCATION.finditer(text) if scan[m.start("sub")] != " "]
        extents = [(m.end(), command_end(scan, depths, m.end())) for m in invocations]
        owned = {}   # flag offset -> invocation index: the innermost (latest starting) invocation whose extent holds it
        for k, (begin, end) in enumerate(extents):
            for m in FLAG.finditer(scan, begin, end):
                owned[m.start(1)] = (k, m.group(1))
        for k, inv in enumerate(invocations):
            sub = inv.group("sub")
            where = "%s:%d" % (rel(doc.path), line_at(starts, inv.start()))
            commands += 1
            if sub.startswith("-"):
                name, options = "octocap", top_options
                used = [(inv.start("sub"), sub.split("=")[0])] if sub.startswith("--") else []
            else:
                if sub not in subcommands:
                    failures.append("FAIL: %s: octocap %s is not a subcommand of octocap (%s)" %
                                    (where, sub, ", ".join(sorted(subcommands)) or "its --help lists none"))
                    continue
                name = "octocap " + sub
                ok, options, nested, help_text = help_options(binary, [sub], cache)
                if not ok:
                    failures.append("FAIL: %s: `%s --help` failed: %s" % (where, name, help_text.strip()[:200]))
                    continue
                # A nested command (octocap security add): its own options.
                word = re.match(r"[ \t]+([a-z][a-z-]*)", text[inv.end():])
                if word and word.group(1) in nested:
                    name += " " + word.group(1)
                    ok, options, _, help_text = help_options(binary, [sub, word.group(1)], cache)
                    if not ok:
                        failures.append("FAIL: %s: `%s --help` failed: %s" % (where, name, help_text.strip()[:200]))
                        continue
                used = []
            used += sorted((offset, flag) for offset, (owner, flag) in owned.items() if owner == k)
            for offset, flag in used:
                flags += 1
                if flag not in options:
                    failures.append("FAIL: %s:%d: %s %s is not an option of %s" %
                                    (rel(doc.path), line_at(starts, offset), name, flag, name))
    return commands, flags


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: check-docs.py SOURCE_DIR OCTOCAP_BINARY\n")
        return 2
    root, binary = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    if not os.access(binary, os.X_OK):
        sys.stderr.write("check-docs.py: %s is not an executable\n" % binary)
        return 2
    files = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    files = [f for f in files if os.path.isfile(f)]
    if not files:
        sys.stderr.write("check-docs.py: no README.md or docs/*.md under %s\n" % root)
        return 2

    def rel(path):
        return os.path.relpath(path, root)

    failures, docs_cache, help_cache = [], {}, {}
    top_ok, _, subcommands, top_text = help_options(binary, [], help_cache)
    if not top_ok or not subcommands:
        sys.stderr.write("check-docs.py: `%s --help` lists no subcommands:\n%s\n" % (binary, top_text))
        return 2
    links = commands = flags = 0
    for path in files:
        doc = docs_cache.setdefault(os.path.normpath(path), Markdown(path))
        links += check_links(doc, root, docs_cache, rel, failures)
        c, f = check_commands(doc, binary, help_cache, rel, failures)
        commands += c
        flags += f
    for line in failures:
        print(line)
    if failures:
        print("check-docs: %d problem(s) in %d files" % (len(failures), len(files)))
        return 1
    print("check-docs: %d files: %d relative links resolve; %d octocap commands, %d flags, all options of %s" %
          (len(files), links, commands, flags, rel(binary) if binary.startswith(root) else binary))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
