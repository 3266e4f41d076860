#!/usr/bin/python3
"""How well the particles of P1 cells and of pairs of cells see the affine
fields, for regular particle layouts (doc/stability.md, "Sampling of P1
cells", the table of the best pair's lambda / fill).

A 4 x 4 patch of blocks (criss-cross: 4 triangles a block; diagonal: 2),
particles at the regular positions ((i + 1/2) / nx, (j + 1/2) / ny) of
each block, each in the first triangle that contains it. For each cell
that holds particles: lambda of its own particles, and the best over the
pairs it forms with a cell sharing a vertex (both holding particles) of
lambda_min(E^-1/2 G E^-1/2) / fill, G = sum m p p^T over the pair's
particles, E = int p p^T over the pair, p = (1, x, y): 1 when the
particles integrate the affine fields like the exact integral, 0 when they
lie on a line. Prints the smallest and the median over the cells.

    /usr/bin/python3 contrib/studies/stability/p1_pair_sampling.py
"""
import numpy as np
def block_tris(kind,i,j):
    c=(i+.5,j+.5); a=(i,j);b=(i+1,j);d=(i+1,j+1);e=(i,j+1)
    if kind=='cc': return [(a,b,c),(b,d,c),(d,e,c),(e,a,c)]
    return [(a,b,d),(a,d,e)]
def bary(t,p):
    (x1,y1),(x2,y2),(x3,y3)=t
    T=np.array([[x1-x3,x2-x3],[y1-y3,y2-y3]])
    l=np.linalg.solve(T,np.array(p)-np.array([x3,y3]))
    return np.array([l[0],l[1],1-l[0]-l[1]])
def area(t):
    (x1,y1),(x2,y2),(x3,y3)=t
    return abs((x2-x1)*(y3-y1)-(x3-x1)*(y2-y1))/2
# exact int over triangle of p p^T with p=(1,x,y): quadrature degree 2 (midpoints)
def exact(t,x0):
    A=area(t); G=np.zeros((3,3))
    P=[np.array(v) for v in t]
    for q in [(P[0]+P[1])/2,(P[1]+P[2])/2,(P[2]+P[0])/2]:
        p=np.array([1,q[0]-x0[0],q[1]-x0[1]]); G+=A/3*np.outer(p,p)
    return G
N=4
for kind in ['cc','diag']:
  for nx,ny in [(1,1),(2,1),(2,2),(3,2),(3,3),(4,4),(8,8)]:
    tris=[]; 
    for i in range(N):
      for j in range(N): tris+=block_tris(kind,i,j)
    parts=[[] for _ in tris]
    for i in range(N):
      for j in range(N):
        for a in range(nx):
          for b in range(ny):
            p=(i+(a+.5)/nx, j+(b+.5)/ny)
            for k,t in enumerate(tris):
              if bary(t,p).min()>-1e-12: parts[k].append(p); break
    m=1/(nx*ny)
    res=[]
    for k,t in enumerate(tris):
      if not parts[k]: continue
      best=0
      for k2,t2 in enumerate(tris):
        if k2==k or not parts[k2] or not (set(t)&set(t2)): continue
        x0=np.mean(np.array(t+t2),axis=0)
        G=exact(t,x0)+exact(t2,x0)
        Gp=sum(m*np.outer([1,p[0]-x0[0],p[1]-x0[1]],[1,p[0]-x0[0],p[1]-x0[1]]) for p in parts[k]+parts[k2])
        fill=m*(len(parts[k])+len(parts[k2]))/(area(t)+area(t2))
        L=np.linalg.cholesky(G); Li=np.linalg.inv(L)
        lam=np.linalg.eigvalsh(Li@Gp@Li.T).min()/fill
        best=max(best,lam)
      # own
      x0=np.mean(np.array(t),axis=0); G=exact(t,x0)
      Gp=sum(m*np.outer([1,p[0]-x0[0],p[1]-x0[1]],[1,p[0]-x0[0],p[1]-x0[1]]) for p in parts[k])
      fill=m*len(parts[k])/area(t); Li=np.linalg.inv(np.linalg.cholesky(G))
      own=np.linalg.eigvalsh(Li@Gp@Li.T).min()/fill
      res.append((own,best))
    r=np.array(res)
    print(kind,nx,ny,'cells',len(r),'own<0.01:',int((r[:,0]<0.01).sum()),'best pair min %.3f median %.3f'%(r[:,1].min(),np.median(r[:,1])), ' own min %.3f'%r[:,0].min())
