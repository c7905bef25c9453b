import sys, struct
def read(path):
    f=open(path,'rb'); kind=f.readline().strip(); w,h=map(int,f.readline().split()); scale=float(f.readline())
    n=w*h*(3 if kind==b'PF' else 1); fmt=('<' if scale<0 else '>')+'%df'%n
    d=struct.unpack(fmt,f.read(4*n)); return w,h,d
for p in sys.argv[1:]:
    w,h,d=read(p); c=3
    m=[sum(d[i::3])/(w*h) for i in range(3)]
    print(p, ['%.5f'%x for x in m])
