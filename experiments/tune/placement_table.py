#!/usr/bin/python3
"""The placement-at-equal-time table of experiments/tune/NOTES.md from the committed
results (experiments/results/tune-placement-equal-time-{train,validation}-pocl-xeon.json.xz):
per luminaire and height, the mean NMSE of the plain cubature (defaults, tuned) and of
Delaunay + two tuned static samples, and each one's log(NMSE / MCI's NMSE at its own time),
MCI's NMSE read off the scene's MCI curve by log-log interpolation (times made
non-decreasing in N, ~1/t beyond the ends), as tune's equal_time objective does. The last
column times the static samples at the plain straight-line time scaled by the general
kernel's ratio (static=2 over static=0): an estimate, two static samples have no
straight-line form. The second table, from
experiments/results/tune-placement-static1-equal-time-{train,validation}-pocl-xeon.json.xz,
and the third (static2) measure one and two static samples (default and tuned) in their
straight-line forms.
usage: experiments/tune/placement_table.py"""
import os
import json, math, collections, sys, lzma
def load(p):
    recs=[]
    op=lzma.open if p.endswith('.xz') else open
    txt=op(p,'rt').read()
    try: recs=json.loads(txt)['records']
    except Exception:
        recs=[json.loads(l) for l in txt.splitlines() if l.strip()]
        recs=[r.get('record',r) for r in recs]
    return recs
def curve_at(curve,t):
    # curve: list of (N, ms, nmse) sorted by N; times non-decreasing in N (a larger N measured faster takes the smaller one's time)
    pts=[]; tm=0
    for n,ms,m in sorted(curve):
        tm=max(tm,ms); pts.append((tm,m,n))
    # log-log interpolation; beyond ends ~1/t
    if t<=pts[0][0]: return pts[0][1]*pts[0][0]/t, pts[0][2]*t/pts[0][0]
    if t>=pts[-1][0]: return pts[-1][1]*pts[-1][0]/t, pts[-1][2]*t/pts[-1][0]
    for (t0,m0,n0),(t1,m1,n1) in zip(pts,pts[1:]):
        if t0<=t<=t1:
            if t1==t0: return min(m0,m1), n1
            a=(math.log(t)-math.log(t0))/(math.log(t1)-math.log(t0))
            return math.exp(math.log(m0)+a*(math.log(m1)-math.log(m0))), math.exp(math.log(n0)+a*(math.log(n1)-math.log(n0)))
RES = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'results')
P='cubature:corner_inset=0.5662577321985738,dyn_weight=0.3379784245526901,horizon_eps=0.17601618104591,plane_eps=0.21478046004027693'
S='cubature:corner_inset=0.48424505778665794,dyn_weight=0.4169891275137666,horizon_eps=0.15330361519392197,plane_eps=0.10804281657032566,s1=0.4854980468749998,s2=0.5,static=2,t1=0.11015116954824813,t2=0.5,triangulation=delaunay'
PG='cubature:specialize=none,'+P[len('cubature:'):]
print('| set | luminaire | h | plain default | plain tuned | static=2 tuned | NMSE gain of placement | plain tuned ms / log(NMSE/MCI) / wins | static=2 tuned, general kernel: ms / log / wins | static=2 tuned at the estimated straight-line time: ms / log / wins |')
print('|---|---|---|---|---|---|---|---|---|---|')
allrows=collections.defaultdict(list)
for setn in ['train','validation']:
    recs=load(os.path.join(RES, f'tune-placement-equal-time-{setn}-pocl-xeon.json.xz'))
    scenes=collections.OrderedDict()
    for r in recs: scenes.setdefault(r['scene'],[]).append(r)
    groups=collections.OrderedDict()
    for sc,rs in scenes.items():
        curve=[(r.get('n') or r['params']['n'], r['time_ms']['median'], r['nmse']) for r in rs if r['role']=='mci_curve']
        by={r['spec']:r for r in rs if r['role']=='method'}
        lum=rs[0]['luminaire'].split('_')[0]; h=rs[0]['height']
        d=by['cubature']['nmse']; p=by[P]; s=by[S]; pg=by[PG]
        tp=p['time_ms']['median']; ts=s['time_ms']['median']; tpg=pg['time_ms']['median']
        test=tp*ts/tpg
        row=dict(d=d,p=p['nmse'],s=s['nmse'],tp=tp,ts=ts,test=test,
                 lp=math.log(p['nmse']/curve_at(curve,tp)[0]), ls=math.log(s['nmse']/curve_at(curve,ts)[0]), le=math.log(s['nmse']/curve_at(curve,test)[0]))
        groups.setdefault((lum,h),[]).append(row); allrows[setn].append(row)
    def line(setn,lum,h,v):
        m=lambda k: sum(x[k] for x in v)/len(v)
        med=lambda k: sorted(x[k] for x in v)[len(v)//2]
        w=lambda k: sum(x[k]<0 for x in v)
        print(f"| {setn} | {lum} | {h} | {m('d'):.3g} | {m('p'):.3g} | {m('s'):.3g} | {m('p')/m('s'):.2f}x | {med('tp'):.2g} / {m('lp'):+.2f} / {w('lp')} of {len(v)} | {med('ts'):.3g} / {m('ls'):+.2f} / {w('ls')} of {len(v)} | {med('test'):.2g} / {m('le'):+.2f} / {w('le')} of {len(v)} |")
    for (lum,h),v in groups.items(): line(setn,lum,h,v)
    line(setn,'**all**','',allrows[setn])

# Static samples, measured: their straight-line forms (LB_CUB_RECT_DELST) where nothing is
# clipped, the general kernel elsewhere, all timed in the same runs
# (experiments/results/tune-placement-static{1,2}-equal-time-{train,validation}-pocl-xeon.json.xz).
S1='cubature:corner_inset=0.47474030406641377,dyn_weight=0.4438203675431775,horizon_eps=0.15770996468832849,plane_eps=0.0962521955082793,s1=0.5298553466796876,static=1,t1=0.35039991350465294,triangulation=delaunay'
def measured(k, tuned):
    default=f'cubature:triangulation=delaunay,static={k}'
    print()
    print(f'| set | luminaire | h | plain default | plain tuned | static={k} default | static={k} tuned | NMSE gain of placement | plain tuned: ms / log / wins | static={k} default: ms / log / wins | static={k} tuned: ms / log / wins |')
    print('|---|---|---|---|---|---|---|---|---|---|---|')
    allrows=collections.defaultdict(list)
    for setn in ['train','validation']:
        path=os.path.join(RES, f'tune-placement-static{k}-equal-time-{setn}-pocl-xeon.json.xz')
        if not os.path.exists(path): continue
        scenes=collections.OrderedDict()
        for r in load(path): scenes.setdefault(r['scene'],[]).append(r)
        groups=collections.OrderedDict()
        for sc,rs in scenes.items():
            curve=[(r.get('n') or r['params']['n'], r['time_ms']['median'], r['nmse']) for r in rs if r['role']=='mci_curve']
            by={r['spec']:r for r in rs if r['role']=='method'}
            lum=rs[0]['luminaire'].split('_')[0]; h=rs[0]['height']
            p,sd,st=by[P],by[default],by[tuned]
            row=dict(d=by['cubature']['nmse'],p=p['nmse'],sd=sd['nmse'],s=st['nmse'],
                     tp=p['time_ms']['median'],tsd=sd['time_ms']['median'],ts=st['time_ms']['median'])
            for key,t,n in (('lp','tp','p'),('lsd','tsd','sd'),('ls','ts','s')):
                row[key]=math.log(row[n]/curve_at(curve,row[t])[0])
            groups.setdefault((lum,h),[]).append(row); allrows[setn].append(row)
        def line1(setn,lum,h,v):
            m=lambda key: sum(x[key] for x in v)/len(v)
            med=lambda key: sorted(x[key] for x in v)[len(v)//2]
            w=lambda key: sum(x[key]<0 for x in v)
            cell=lambda t,l: f"{med(t):.2g} / {m(l):+.2f} / {w(l)} of {len(v)}"
            print(f"| {setn} | {lum} | {h} | {m('d'):.3g} | {m('p'):.3g} | {m('sd'):.3g} | {m('s'):.3g} | {m('p')/m('s'):.2f}x | {cell('tp','lp')} | {cell('tsd','lsd')} | {cell('ts','ls')} |")
        for (lum,h),v in groups.items(): line1(setn,lum,h,v)
        line1(setn,'**all**','',allrows[setn])
measured(1, S1)
measured(2, S)
