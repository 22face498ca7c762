#!/usr/bin/env python3
"""Summary of rough-on-rough cell samples (doc/rve_cell.md, "rough on rough"): files sg<sigma>_p<p>_s<seed>.dat in the
current directory (written by inputs/in.rve_rough with -var out NAME). Needs numpy (/usr/bin/python3).
Seed means over h; mu, the parts and A_r/A smoothed over 5 points; Rq drops from the start of sliding."""
import numpy as np, glob, re, sys
K, H = 7e-3, 1.19e9  # Steel1020 (potentials/Steel1020.runin)
def load(f): return np.loadtxt(f)[1:]
def smooth(y,n=5):
    if len(y)<n: return y
    k=np.ones(n)/n; return np.convolve(np.pad(y,(n//2,n//2),mode='edge'),k,mode='valid')
rows={}
for f in sorted(glob.glob('sg*_p*_s*.dat')):
    m=re.match(r'sg(\S+)_p(\S+)_s(\d+)\.dat',f); sg,p,sd=float(m[1]),float(m[2]),int(m[3])
    d=load(f); rows.setdefault((sg,p),[]).append(d)
for (sg,p),ds in sorted(rows.items()):
    hmax=min(d[-1,2] for d in ds); hs=np.linspace(0, hmax, 41)[1:]
    def mean(c): return np.mean([np.interp(hs,d[:,2],d[:,c]) for d in ds],axis=0)
    def spread(c):
        if len(ds)<2: return float('nan')
        a,b=[np.interp(hs,d[:,2],d[:,c]) for d in ds[:2]]; r=(a-b)/(a+b); return np.sqrt(np.mean(r*r))
    mu=mean(4); mus=smooth(mu); rq=mean(5); af=mean(7)
    rq0=np.mean([d[0,5] for d in ds]); s_of_h=lambda h: h*H/(K*p)
    ipk=int(np.argmax(mus))
    scale=sg*H/(K*p)
    def h_drop(frac):
        target=rq0*(1-frac); idx=np.where(rq<=target)[0]
        return hs[idx[0]] if len(idx) else float('nan')
    print(f"sigma {sg*1e6:.1f} um, p {p/1e6:g} MPa, {len(ds)} seeds, h to {hmax*1e9:.1f} nm (s {s_of_h(hmax)*1e3:.3f} mm), sigma H/(k p) = {scale*1e3:.2f} mm")
    print(f"   seed-to-seed half-difference RMS: mu {spread(4):.3f} rq {spread(5):.4f} af {spread(7):.3f}")
    print(f"   contacts {np.mean([d[:,10].mean() for d in ds]):.0f}, W/A_r start {p/af[0]/1e6:.0f} MPa end {p/af[-1]/1e6:.0f} MPa")
    sel=[0,4,9,19,29,39]
    print("   h(nm)   ", ' '.join(f"{hs[i]*1e9:7.2f}" for i in sel))
    for c,n in ((4,'mu'),(8,'mu_adh'),(9,'mu_pl'),(5,'Rq(nm)'),(6,'Rsk'),(7,'A_r/A')):
        v=mean(c); v=smooth(v) if c in (4,8,9,7) else v
        if c==5: v=v*1e9
        print(f"   {n:9s}", ' '.join(f"{v[i]:7.4g}" for i in sel))
    print(f"   Rq0 {rq0*1e9:.1f} nm; mu peak {mus[ipk]:.4f} at h {hs[ipk]*1e9:.2f} nm, end {mus[-1]:.4f}")
    for frac in (0.1,0.2,0.3):
        h=h_drop(frac); print(f"   Rq -{frac*100:.0f}%: h {h*1e9:.2f} nm, s {s_of_h(h)*1e3:.3f} mm = {s_of_h(h)/scale:.4f} sigma H/(k p), h/sigma {h/sg:.4f}")
