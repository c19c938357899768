#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
"""The man pages and the bash completion of armstudy, made from its own --help at build time
(so that they say what the program does, option for option).

usage: cli_docs.py ARMSTUDY VERSION OUT_DIR
writes OUT_DIR/man1/armstudy.1.gz, OUT_DIR/man1/armstudy-<command>[-<sub>].1.gz for every
(sub)command `armstudy --help` lists (gzipped reproducibly, as Debian installs man pages),
and OUT_DIR/bash-completion/armstudy. A command's EXAMPLES are the "Examples:" lines of its
--help.
"""
import gzip
import os
import re
import subprocess
import sys

# what armstudy reads from its environment (src/: the getenv calls), for armstudy(1)
ENVIRONMENT = [
    ("ARMSTUDY_TEMPLATE_DIR", "The folder of the report templates and stylesheet (default: "
     "<prefix>/share/armstudy/templates beside the program's <prefix>/bin)."),
    ("ARMSTUDY_CHROMIUM", "The browser --pdf prints with (default: the first of "
     "chromium-headless-shell, chromium, chromium-browser, google-chrome on PATH)."),
    ("ARMSTUDY_FFMPEG", "The ffmpeg that encodes the animations (default: ffmpeg on PATH; "
     "without it the animations have no video)."),
    ("ARMSTUDY_FRAME_WORKER", "The frame helper program (default: armstudy-frames beside "
     "armstudy); empty or 'none': every frame is drawn in armstudy itself, with the same "
     "pixels."),
    ("ARMSTUDY_PHASE_TIMES", "Set (and not 0): run prints one line per case on stderr with "
     "the wall-clock seconds of each phase (solve, rendering, report, PDF)."),
    ("PLPLOT_DRV_DIR", "The folder of PLplot's drivers (armstudy draws with its cairo driver)."),
    ("TMPDIR", "The temporary folder of the PDF printing (default /tmp)."),
]


def help_of(armstudy, words):
    out = subprocess.run([armstudy] + words + ["--help"], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, check=True, text=True,
                         env=dict(os.environ, ARMSTUDY_CHROMIUM="/nonexistent")).stdout
    return out.replace(armstudy, "armstudy")


def parse(text):
    """CLI11's help: the description, the usage, then sections of entries (name, text)."""
    lines = text.rstrip("\n").split("\n")
    description, usage = lines[0], lines[1][len("Usage: "):]
    if description.startswith("armstudy: "):
        description = description[len("armstudy: "):]
    sections, current, footer = [], None, []
    for line in lines[2:]:
        if not line.strip():
            continue
        if re.match(r"^(Positionals|Options|Subcommands):$", line):
            current = (line[:-1], [])
            sections.append(current)
        elif current is not None and re.match(r"^  \S", line) and not re.match(
                r"^  [a-z_]+: ", line):
            parts = re.split(r"\s{2,}", line.strip(), maxsplit=1)
            current[1].append([parts[0], parts[1] if len(parts) > 1 else ""])
        elif current is not None and line.startswith(" " * 30) and current[1]:
            entry = current[1][-1]
            entry[1] = (entry[1] + " " + line.strip()).strip()
        else:  # the footer: the studies, the exit codes and the examples
            current = None
            footer.append(line)
    return description, usage, sections, footer


def roff(text):
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return "\\&" + text if text[:1] in (".", "'") else text


def examples_of(footer):
    """The footer's "Examples:" lines: (what it does, the command), a "# what" line before its
    command."""
    if "Examples:" not in footer:
        return []
    examples, what = [], ""
    for line in footer[footer.index("Examples:") + 1:]:
        if not line.startswith("  "):
            break
        line = line.strip()
        if line.startswith("# "):
            what = line[2:]
        else:
            examples.append((what, line))
            what = ""
    return examples


def page(name, version, description, usage, sections, footer, words, children, see_also):
    title = name.upper()
    out = [f'.TH {title} 1 "" "armstudy {version}" "armstudy manual"',
           ".SH NAME", f"{roff(name)} \\- {roff(description)}",
           ".SH SYNOPSIS", f".B {roff(' '.join(['armstudy'] + words))}",
           roff(usage.split(" ", len(words) + 1)[-1] if words else usage.split(" ", 1)[1]),
           ".SH DESCRIPTION", roff(description) + "."]
    names = {"Positionals": "ARGUMENTS", "Options": "OPTIONS", "Subcommands": "COMMANDS"}
    for head, entries in sections:
        out.append(".SH " + names[head])
        for entry_name, text in entries:
            out += [".TP", f".B {roff(entry_name)}", roff(text)]
            if head == "Subcommands":
                out += [".br", f"See \\fB{roff('-'.join(['armstudy'] + words + [entry_name]))}\\fR(1)."]
    studies = [f for f in footer if re.match(r"^  [a-z_]+: ", f)]
    if studies:
        out.append(".SH STUDIES")
        for s in studies:
            study, text = s.strip().split(": ", 1)
            out += [".TP", f".B {roff(study)}", roff(text)]
    exits = [f for f in footer if f.startswith("Exit codes: ")]
    if exits:
        out += [".SH EXIT STATUS", roff(exits[0][len("Exit codes: "):])]
    examples = examples_of(footer)
    if examples:
        out.append(".SH EXAMPLES")
        for what, command in examples:
            out += [".PP", roff(what) if what else "", ".RS 4", ".EX", roff(command), ".EE", ".RE"]
            out = [o for o in out if o]
    if not words:
        out.append(".SH ENVIRONMENT")
        for var, text in ENVIRONMENT:
            out += [".TP", f".B {var}", roff(text)]
        out += [".SH FILES", ".TP", ".I <prefix>/share/armstudy/templates",
                "The report templates and stylesheet.", ".TP",
                ".I <prefix>/share/armstudy/results.schema.json",
                "The JSON Schema of results.json.", ".TP",
                ".I <prefix>/share/doc/armstudy",
                "The documentation; examples/cases holds the bundled case files."]
    out += [".SH SEE ALSO", ", ".join(f"\\fB{roff(s)}\\fR(1)" for s in see_also if s != name)]
    return "\n".join(out) + "\n"


def main():
    armstudy, version, out_dir = sys.argv[1:4]
    os.makedirs(os.path.join(out_dir, "man1"), exist_ok=True)
    os.makedirs(os.path.join(out_dir, "bash-completion"), exist_ok=True)
    # every command path, breadth first: [], [run], [sweep], [sweep, expand], ...
    pending, parsed = [[]], []
    while pending:
        words = pending.pop(0)
        description, usage, sections, footer = parse(help_of(armstudy, words))
        children = [e[0] for head, es in sections if head == "Subcommands" for e in es]
        parsed.append((words, description, usage, sections, footer, children))
        pending += [words + [c] for c in children]
    names = ["-".join(["armstudy"] + p[0]) for p in parsed]
    for (words, description, usage, sections, footer, children), name in zip(parsed, names):
        text = page(name, version, description, usage, sections, footer, words, children, names)
        # mtime 0 and no file name: the same bytes at every build (gzip -9n)
        with open(os.path.join(out_dir, "man1", name + ".1.gz"), "wb") as raw:
            with gzip.GzipFile(filename="", mode="wb", compresslevel=9, fileobj=raw,
                               mtime=0) as f:
                f.write(text.encode())
    # bash completion: the (sub)commands, then each command's options; files otherwise
    cases = []
    for words, _, _, sections, _, children in parsed:
        options = [o for head, es in sections if head == "Options" for e in es
                   for o in re.findall(r"(?:^|,)(-{1,2}[A-Za-z][\w-]*)", e[0].split(" ")[0])]
        key = " ".join(words)
        cases.append(f'    "{key}") commands="{" ".join(children)}"; '
                     f'options="{" ".join(options)}" ;;')
    script = """# bash completion for armstudy (generated from its --help by scripts/cli_docs.py)
_armstudy() {
  local cur path="" word commands options i
  cur="${COMP_WORDS[COMP_CWORD]}"
  # the (sub)command path typed so far: the words before the cursor that name one
  for ((i = 1; i < COMP_CWORD; i++)); do
    word="${COMP_WORDS[i]}"
    case "${path:+$path }$word" in
%s
    esac
  done
  case "$path" in
%s
  esac
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
  elif [[ -n "$commands" ]]; then
    COMPREPLY=($(compgen -W "$commands" -- "$cur"))
  else
    COMPREPLY=($(compgen -f -- "$cur"))
  fi
}
complete -o filenames -o bashdefault -F _armstudy armstudy
""" % ("\n".join(f'      "{" ".join(p[0])}") path="{" ".join(p[0])}" ;;' for p in parsed if p[0]),
       "\n".join(cases))
    with open(os.path.join(out_dir, "bash-completion", "armstudy"), "w") as f:
        f.write(script)


if __name__ == "__main__":
    main()
