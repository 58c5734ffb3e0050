#!/usr/bin/env python3
"""ncu_summary.py NCU.txt... -- the GPU time per kernel of a run, from the output of
  ncu --cache-control none --clock-control none --metrics gpu__time_duration.sum \
      --print-summary per-kernel flipflop hull3 IN --backend cuda -o OUT
summed over the launches of each functor (hull3's, by name; CUB's by kernel), largest
first: total time, launches, name. Used for docs/bench/gpu_h200_hull3_ncu_2026-11-28.txt."""
import re,sys
def parse(path):
    rows=[]; cur=None
    for line in open(path):
        m=re.match(r'\s+(void .*|[A-Za-z_].*) \((\d+), 1, 1\)x\((\d+), 1, 1\), Device 0, CC 9.0, Invocations (\d+)',line)
        if m:
            cur=[m.group(1),int(m.group(2)),int(m.group(4))]; continue
        m=re.match(r'\s+gpu__time_duration.sum\s+(\w+)\s+([\d.]+)\s+([\d.]+)\s+([\d.]+)',line)
        if m and cur:
            unit=m.group(1); f={'us':1,'ms':1000,'ns':1e-3}[unit]
            avg=float(m.group(4))*f
            rows.append((cur[0],cur[1],cur[2],avg,avg*cur[2])); cur=None
    return rows
def short(name):
    for pat in [r'hull3_detail::(\w+)<', r'hull3_detail::(\w+)\b', r'(DeviceSelect\w*|DeviceReduce\w*|DeviceScan\w*|DeviceRadix\w*|DeviceMerge\w*|Device\w+Kernel\w*)', r'__(\w+)::']:
        ms=re.findall(pat,name)
        if ms:
            if pat.startswith('hull3'):
                # prefer the functor names inside
                names=[x for x in re.findall(r'hull3_detail::(\w+)',name) if x not in ('Atomic',)]
                m2=re.search(r'Pass<hull3_detail::(\w+), ([01])>',name)
                if m2: return '%s (%s pass)'%(m2.group(1),('first','second (exact)')[int(m2.group(2))])
                return '+'.join(dict.fromkeys(names))[:70]
            return ms[0]
    return name[:60]
for path in sys.argv[1:]:
    rows=parse(path)
    agg={}
    for n,g,inv,avg,tot in rows:
        k=short(n)
        a=agg.setdefault(k,[0,0.0]); a[0]+=inv; a[1]+=tot
    total=sum(v[1] for v in agg.values()); launches=sum(v[0] for v in agg.values())
    print(f'== {path}: {total/1000:.3f} ms GPU time in {launches} launches')
    for k,v in sorted(agg.items(), key=lambda kv:-kv[1][1])[:28]:
        print(f'{v[1]/1000:8.3f} ms {v[0]:6d}  {k}')
