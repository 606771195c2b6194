#!/usr/bin/python3
"""Draws docs/hybrid-layer.png, the README's picture: the cells of the built-in dam block behind a
cut normal to its pipe, coloured by kind. VTK reads the mesh; Pillow paints the faces back to
front (VTK's own renderer needs a display).

    build/release/tools/tubemesh mesh --quiet -o dam.vtu && docs/hybrid_layer.py dam.vtu docs/hybrid-layer.png
"""
import sys
import vtk, numpy as np
from PIL import Image, ImageDraw, ImageFont
from vtk.util.numpy_support import vtk_to_numpy as v2n
r=vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()
g=r.GetOutput()
kind=v2n(g.GetCellData().GetArray('kind'))
cc=vtk.vtkCellCenters(); cc.SetInputData(g); cc.Update()
c=v2n(cc.GetOutput().GetPoints().GetData())
hx=c[kind==2]
p0=hx[np.abs(hx[:,1]-12.5)<0.3].mean(0)
near=hx[np.linalg.norm(hx-p0,axis=1)<1.0]
t=np.linalg.svd(near-near.mean(0))[2][0]
d=(c-p0)@t
radial=np.linalg.norm((c-p0)-np.outer(d,t),axis=1)
keep=(d<=0)&(d>-0.10)&(radial<0.17)
ids=vtk.vtkIdTypeArray()
for i in np.nonzero(keep)[0]: ids.InsertNextValue(int(i))
node=vtk.vtkSelectionNode(); node.SetFieldType(vtk.vtkSelectionNode.CELL); node.SetContentType(vtk.vtkSelectionNode.INDICES); node.SetSelectionList(ids)
sel=vtk.vtkSelection(); sel.AddNode(node)
ex=vtk.vtkExtractSelection(); ex.SetInputData(0,g); ex.SetInputData(1,sel); ex.Update()
geo=vtk.vtkDataSetSurfaceFilter(); geo.SetInputData(ex.GetOutput()); geo.Update()
s=geo.GetOutput()
P=v2n(s.GetPoints().GetData())
K=v2n(s.GetCellData().GetArray('kind'))
polys=[]
for i in range(s.GetNumberOfCells()):
    cell=s.GetCell(i); polys.append([cell.GetPointId(j) for j in range(cell.GetNumberOfPoints())])
# camera: look along -t (towards the kept slab), tilted
up=np.array([0,0,1.0]); side=np.cross(t,up); side/=np.linalg.norm(side)
view=-(t+0.35*side+0.30*up); view/=np.linalg.norm(view)   # direction the camera looks
right=np.cross(view,up); right/=np.linalg.norm(right); vup=np.cross(right,view)
Q=P-p0
x=Q@right; y=Q@vup; z=Q@view
W,H=720,540; scale=0.88*min(W,H)/(2*0.17)
px=W/2+scale*x; py=H/2-scale*y
col={0:(92,153,217),1:(237,140,64),2:(115,184,77)}
light=-view+0.5*vup; light/=np.linalg.norm(light)
img=Image.new('RGB',(W,H),'white'); dr=ImageDraw.Draw(img)
order=sorted(range(len(polys)),key=lambda i:-np.mean(z[polys[i]]))
for i in order:
    pid=polys[i]
    a,b,cc_=Q[pid[0]],Q[pid[1]],Q[pid[2]]
    n=np.cross(b-a,cc_-a); nn=np.linalg.norm(n)
    f=0.55+0.45*abs((n/nn)@light) if nn>0 else 1
    base=col[int(K[i])]
    fill=tuple(int(min(255,v*f)) for v in base)
    dr.polygon([(px[j],py[j]) for j in pid],fill=fill,outline=(40,40,40))
try: font=ImageFont.truetype('/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf',18)
except Exception: font=None
yy=12
for name,k in [('hexahedra (swept ring)',2),('pyramids',1),('tetrahedra',0)]:
    dr.rectangle([12,yy+3,28,yy+19],fill=col[k],outline=(40,40,40)); dr.text((36,yy),name,fill=(30,30,30),font=font); yy+=26
img=img.quantize(colors=64)
img.save(sys.argv[2], optimize=True)
