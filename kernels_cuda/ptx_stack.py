#!/usr/bin/env python3
"""ptx_stack.py — the per-thread stack a CUDA kernel needs, from its PTX.

Usage: ptx_stack.py FILE.ptx [N] [-v]

Every PTX function declares its local memory as one `__local_depot` array; a
thread's stack is the deepest chain of depots along the call graph from its
entry (no recursion here: predicates/exact_expansion.hpp), which is what the
driver raises cudaLimitStackSize to at a launch (ptxas -v reports the same
sum, plus a few bytes of spills). Prints the N entries with the deepest
chains (default 15); -v also the 25 largest depots of single functions.
Get the PTX with nvcc ... -arch=sm_90 -ptx SRC.cu -o FILE.ptx (cicc only,
minutes faster than a full compile).
"""
import functools
import re
import subprocess
import sys


def parse(lines):
    depot, calls, entries = {}, {}, set()
    cur, pending = None, False
    head = re.compile(r'^(?:\.visible\s+|\.weak\s+)?\.(entry|func)\s+(?:\([^)]*\)\s*)?(\w+)')
    for line in lines:
        m = head.match(line)
        if m and not line.rstrip().endswith(';'):  # a definition, not a prototype
            cur = m.group(2)
            depot.setdefault(cur, 0)
            calls.setdefault(cur, set())
            if m.group(1) == 'entry':
                entries.add(cur)
            continue
        if cur is None:
            continue
        m = re.search(r'__local_depot\d+\[(\d+)\]', line)
        if m:
            depot[cur] = int(m.group(1))
        if pending:  # `call.uni (retval0),` then the callee on the next line
            m = re.match(r'\s*(\w+)', line)
            if m:
                calls[cur].add(m.group(1))
                pending = False
            continue
        if re.search(r'\bcall(\.uni)?\b', line):
            m = re.search(r'call(?:\.uni)?\s*(?:\([^)]*\),\s*)?(\w+)\s*,?\s*\(', line)
            if m:
                calls[cur].add(m.group(1))
            else:
                pending = True
    return depot, calls, entries


def main():
    args = [a for a in sys.argv[1:] if a != '-v']
    if not args:
        sys.exit(__doc__)
    with open(args[0]) as f:
        depot, calls, entries = parse(f.read().split('\n'))
    top = int(args[1]) if len(args) > 1 else 15

    @functools.lru_cache(None)
    def deepest(fn):
        return depot.get(fn, 0) + max([deepest(c) for c in calls.get(fn, ()) if c != fn] or [0])

    def demangle(name):
        out = subprocess.run(['c++filt'], input=name, capture_output=True, text=True).stdout.strip()
        out = (out or name).replace('flipflop::', '')
        at = out.find('kernels_cuda::')  # a thrust/CUB kernel: show the functor it runs
        return out if at < 0 else '... ' + out[at:]

    for d, e in sorted(((deepest(e), e) for e in entries), reverse=True)[:top]:
        print(f'{d:8d} bytes (own {depot[e]:6d})  {demangle(e)[:150]}')
    if '-v' in sys.argv:
        for fn in sorted(depot, key=lambda f: -depot[f])[:25]:
            print(f'  {depot[fn]:8d} {demangle(fn)[:160]}')


if __name__ == '__main__':
    main()
