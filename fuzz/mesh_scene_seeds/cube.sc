camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [
  trans [ object mesh [ file m.obj diffuse 1 0 0 texture t.png 1 1 ] ]
  trans [ translate 1 0 0 rotate 0 1 0 30 object mesh [ file m.obj reflect .5 .5 .5 transparent .5 .5 .5 ior 1.5 emit .2 .2 .2 ] ]
]
===m.obj===
# a cube
v -.5 -.5 -.5
v .5 -.5 -.5
v .5 .5 -.5
v -.5 .5 -.5
v -.5 -.5 .5
v .5 -.5 .5
v .5 .5 .5
v -.5 .5 .5
vn 0 0 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
f 5/1/1 6/2/1 7/3/1 8/4/1
f 2 1 4 3
f 1 5 8 4
f 6 2 3 7
f 4//1 8//1 7//1 3//1
f 1 2 6 5
