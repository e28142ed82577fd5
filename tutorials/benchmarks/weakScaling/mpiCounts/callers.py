#!/usr/bin/env python3
"""The messages a rank sent, by the code that sent them.

Reads the mpiTrace.<rank> files that mpiCounts writes with MPICOUNTS_TRACE
(each distinct call stack with its number of messages), names each message by the first function of its
stack that is not MPI's or a communication routine of OpenFOAM's (Pstream's
gathers, scatters, reductions and exchanges), and prints a markdown table:
a row a function, a column a trace.

    callers.py label=path/mpiTrace.0 ...   (the last "=" splits)
"""
import collections, re, subprocess, sys

# Functions that only carry a message for their caller
carrier = re.compile(
    r"^(P?MPI_|sent$|trace$)|Pstream|reduce|Reduce|gather|scatter|combine"
    r"|mapDistribute|syncTools|allReduce")
frame = re.compile(r"^(\S+?)\(([^)+]*)(\+0x[0-9a-f]+)?\)")

def stacks(path):
    text = open(path, errors="replace").read()
    for count, block in re.findall(r"^send (\d+)\n(.*?)^end$", text, re.S | re.M):
        yield int(count), [m.groups()[:2] for m in map(frame.match, block.splitlines()) if m]

def demangle(names):
    names = sorted(n for n in names if n)
    out = subprocess.run(["c++filt"], input="\n".join(names),
                         capture_output=True, text=True).stdout.splitlines()
    return dict(zip(names, out))

def caller(stack, names):
    for lib, sym in stack:
        name = names.get(sym, sym)
        if name and not carrier.search(name):
            return re.sub(r"\(.*", "", name)
    return "(unnamed)"

def main(args):
    traces = [a.rsplit("=", 1) for a in args]
    parsed = {label: list(stacks(path)) for label, path in traces}
    names = demangle({s for st in parsed.values() for _, f in st for _, s in f})
    counts = {}
    for label, st in parsed.items():
        counts[label] = collections.Counter()
        for n, frames in st:
            counts[label][caller(frames, names)] += n
    rows = collections.Counter()
    for c in counts.values():
        rows.update(c)
    labels = [label for label, _ in traces]
    print("| sent by | " + " | ".join(labels) + " |")
    print("|---|" + "---:|"*len(labels))
    for name, _ in rows.most_common():
        print("| `%s` | " % name
              + " | ".join(str(counts[l][name]) for l in labels) + " |")
    print("| all | " + " | ".join(str(sum(counts[l].values())) for l in labels) + " |")

if __name__ == "__main__":
    main(sys.argv[1:])
