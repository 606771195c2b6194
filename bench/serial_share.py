#!/usr/bin/python3
"""The tet step's serial share, from a 1-thread perf profile with call graphs: the samples under
build_tets with no oneTBB parallel construct (parallel_for, parallel_invoke, parallel_sort, ...)
on their stack run on one core at any thread count. Contention on a shared machine stretches
wall times but not this split, so it measures what a second core can take over.

  perf record -F 1000 --call-graph dwarf,16384 -o X.data tubemesh mesh ... --threads 1
  perf script -i X.data | /usr/bin/python3 bench/serial_share.py 1000 [depth]
"""
import sys, collections, re
freq = float(sys.argv[1]); depth = int(sys.argv[2]) if len(sys.argv) > 2 else 3
PAR = ('start_for<', 'start_reduce<', 'start_deterministic_reduce<', 'parallel_invoke', 'invoke_subroot_task', 'function_invoker<', 'task_group', 'start_scan<', 'parallel_sort', 'quick_sort_pretest', 'start_parallel_for_each')
def short(s):
    s = re.sub(r'\(.*', '', s)  # drop args
    s = re.sub(r"\+0x[0-9a-f]+$", "", s)
    s = s.replace('tubemesh::', '').replace('(anonymous namespace)::', '')
    return s[:70]
samples = []; cur = []
for line in sys.stdin:
    if not line.strip():
        if cur: samples.append(cur); cur = []
        continue
    if line[0] in ' \t':
        m = re.match(r'\s*[0-9a-f]+\s+(.*?)\s+\((.*)\)\s*$', line)
        if m: cur.append((m.group(1), m.group(2)))
    else:
        if cur: samples.append(cur)
        cur = []
if cur: samples.append(cur)
tot = 0; ser = 0; paths = collections.Counter(); leaves = collections.Counter(); top = collections.Counter(); topser = collections.Counter()
for st in samples:
    names = [f for f, d in st]
    idx = [i for i, n in enumerate(names) if 'tets::build_tets' in n]
    if not idx: continue
    tot += 1
    b = idx[-1]
    inner = names[:b]  # leaf first
    # direct child of build_tets
    child = short(inner[-1]) if inner else 'build_tets'
    top[child] += 1
    if any(any(p in n for p in PAR) for n in inner) or any('libtbb' in d for f, d in st[:b]):
        continue
    ser += 1; topser[child] += 1
    chain = [short(n) for n in reversed(inner) if 'tubemesh' in n or 'nanoflann' in n or 'std::' in n][:depth]
    paths[' > '.join(chain) or 'build_tets'] += 1
    leaves[short(inner[0]) if inner else 'build_tets'] += 1
dt = 1 / freq
print(f'build_tets: {tot} samples ({tot*dt:.2f} s), outside parallel constructs {ser} ({ser*dt:.2f} s, {100*ser/max(tot,1):.1f} %)')
print('\nby phase (child of build_tets): total / serial')
for k, c in top.most_common(): print(f'  {c*dt:7.3f} s  {topser[k]*dt:7.3f} s  {k}')
print('\nserial by path:')
for k, c in paths.most_common(45): print(f'  {c*dt*1000:7.1f} ms  {k}')
print('\nserial by leaf:')
for k, c in leaves.most_common(25): print(f'  {c*dt*1000:7.1f} ms  {k}')
