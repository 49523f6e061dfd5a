#!/usr/bin/env python3
"""The cpu oracle at one thread against two (--threads 1 / 2), one vissort binary, runs
alternated, medians (this VM is noisy): the workloads of docs/benchmarks.md, "Threads".

    python3 scripts/compare-threads.py [RUNS] [--tool build/vissort]

Needs Debian's assimp-testmodels for the engine and the IFC house."""
import json
import statistics
import subprocess
import sys

B = sys.argv[sys.argv.index("--tool") + 1] if "--tool" in sys.argv else "build/vissort"
M = "/usr/share/assimp/models"
def run(args,t):
    out=subprocess.run([B]+args+['--threads',str(t),'--json','-','-q'],capture_output=True,text=True,check=True).stdout
    d=json.loads(out); fr=d.get('frames',[d])
    return statistics.median(f['stats']['ms'] for f in fr)
cases={
 'bunnies object':['order','builtin:bunnies','--eye','6,4.5,10.5','--target','0,0,0','--up','0,1,0','--fov','45','--size','1024x768','--path','orbit','--frames','11','--level','object'],
 'bunnies triangle':['order','builtin:bunnies','--eye','6,4.5,10.5','--target','0,0,0','--up','0,1,0','--fov','45','--size','1024x768','--path','orbit','--frames','11','--level','triangle'],
 'bunnies multistage':['order','builtin:bunnies','--eye','6,4.5,10.5','--target','0,0,0','--up','0,1,0','--fov','45','--size','1024x768','--path','orbit','--frames','11','--level','multistage'],
 'engine 1024':['order',M + '/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb','--size','1024x1024'],
 'IFC house 512':['order',M + '/IFC/AC14-FZK-Haus.ifc','--size','512x512'],
 'pile 1024x768':['order','builtin:pile','--size','1024x768'],
 'plant walk 1600x1200':['order','builtin:powerplant','--path','scene','--frames','11','--size','1600x1200'],
}
runs = int(sys.argv[1]) if len(sys.argv) > 1 and sys.argv[1].isdigit() else 3
for name,a in cases.items():
    r={1:[],2:[]}
    for i in range(runs):
        for t in (1,2): r[t].append(run(a,t))
    m1,m2=statistics.median(r[1]),statistics.median(r[2])
    print(f"{name:24s} 1 thread {m1:8.1f} ms  2 threads {m2:8.1f} ms  {m2/m1:.2f}x  ({[round(x) for x in r[1]]} / {[round(x) for x in r[2]]})",flush=True)
