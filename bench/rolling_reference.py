#!/usr/bin/python3
"""Steady rolling of the cask on its rim, by an integration independent of caskdem's model.

The rigid cylinder (the source paper's 1/3 model) on a continuous rim: the contact is the lowest
point of the base circle found at each instant, pushed by a stiff penalty spring and held from
slipping by a stiff viscous force; Euler's equations and the quaternion by scipy's LSODA.
Released in the steady rolling derived in docs/cask3d.md ("Rolling on the rim"), it keeps its
tilt and precesses at the derived rate: the check of that formula, which a ring of contact
points cannot meet (the same page).

usage: bench/rolling_reference.py        (about a minute)
"""
import numpy as np
from scipy.integrate import solve_ivp
m=8743*np.pi*0.475**2*2.033; R=0.475; H=2.033; h=H/2; g=9.80665
I1=m*(R*R/4+H*H/12); I3=m*R*R/2
alpha=np.arctan2(R,h); beta=0.5*alpha
lean=h*np.sin(beta)-R*np.cos(beta)
Om=np.sqrt(m*g*lean/(np.sin(beta)*((I3-I1)*np.cos(beta)+I3*lean/R))); ws=Om*lean/R
print('Omega',Om,'ws',ws)
def quat_to_R(q):
    w,x,y,z=q
    return np.array([[1-2*(y*y+z*z),2*(x*y-w*z),2*(x*z+w*y)],[2*(x*y+w*z),1-2*(x*x+z*z),2*(y*z-w*x)],[2*(x*z-w*y),2*(y*z+w*x),1-2*(x*x+y*y)]])
kn=1e10; cn=2*0.05*np.sqrt(kn*m); ct=5e6
yhat=np.array([0,1.,0])
def rhs(t,s):
    x=s[0:3]; v=s[3:6]; q=s[6:10]; wb=s[10:13]
    q=q/np.linalg.norm(q); Rm=quat_to_R(q)
    e=Rm[:,1]; w=Rm@wb
    C=x-h*e  # base centre (COM on axis at h)
    p=-yhat+np.dot(yhat,e)*e; f=p/np.linalg.norm(p)
    P=C+R*f
    lever=P-x
    vP=v+np.cross(w,lever)
    F=np.zeros(3)
    if P[1]<0:
        Fn=max(0.0,-kn*P[1]-cn*vP[1]); F[1]=Fn
        F[0]=-ct*vP[0]; F[2]=-ct*vP[2]
    tau=np.cross(lever,F)
    a=F/m-np.array([0,g,0])
    tb=Rm.T@tau
    I=np.array([I1,I3,I1]); Lb=I*wb
    dwb=(tb-np.cross(wb,Lb))/I
    W,X,Y,Z=q; wx,wy,wz=wb
    dq=0.5*np.array([-X*wx-Y*wy-Z*wz, W*wx+Y*wz-Z*wy, W*wy-X*wz+Z*wx, W*wz+X*wy-Y*wx])
    return np.concatenate([v,a,dq,dwb])
# initial: lean toward +x by beta: axis e=(sin b, cos b, 0): rotate about z by -beta
q0=np.array([np.cos(beta/2),0,0,-np.sin(beta/2)])
Rm=quat_to_R(q0); e=Rm[:,1]
# pivot at P=(?,0,?) : place COM so that P at y = -mg/kn
p=-yhat+np.dot(yhat,e)*e; f=p/np.linalg.norm(p)
x0=-(-h*e+R*f); x0[1]+= -m*g/kn
w=Om*yhat+ws*e; wb0=Rm.T@w
s0=np.concatenate([x0,[0,0,0],q0,wb0])
T=10*2*np.pi/Om
sol=solve_ivp(rhs,[0,T],s0,method='LSODA',rtol=1e-8,atol=1e-10,max_step=1e-3)
az=[];tilt=[]
for k in range(sol.y.shape[1]):
    q=sol.y[6:10,k]; q=q/np.linalg.norm(q); e=quat_to_R(q)[:,1]
    az.append(np.arctan2(e[2],e[0])); tilt.append(np.arctan2(np.hypot(e[0],e[2]),e[1]))
az=np.unwrap(az); tilt=np.array(tilt)
print('rate',(az[-1]-az[0])/(sol.t[-1]-sol.t[0]),'tilt/beta range',tilt.min()/beta,tilt.max()/beta)
