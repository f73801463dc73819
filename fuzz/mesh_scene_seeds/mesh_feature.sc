# mesh.sc -- triangle meshes from OBJ files (`object mesh [ file F ... ]`, scene-format.md §9.3).
#
# blob.obj is a displaced, subdivided sphere of 5,120 triangles made by ../meshes/generate.py
# (nothing downloaded). It is read once and drawn 13 times: the big textured blob in the middle
# (its file's texture coordinates, the texture repeated 4 x 2 times), a glass one in front that
# refracts and casts a tinted shadow, and a ring of ten small mirror and matte blobs placed by one
# mastersubgraph instanced ten times. Smooth shading comes from the file's vertex normals.

background [ color 0.12 0.14 0.2 ]

camera [
  eye 0 2.6 6.5
  focus 0 0.6 0
  up 0 1 0
  angle 42
]

light [ type point position 4 7 5 color 0.9 0.9 0.85 ]
light [ type directional direction -0.3 -1 -0.6 color 0.25 0.25 0.3 ]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 14 1 14
    object cube [ ambient 0.05 0.05 0.05 diffuse 0.55 0.55 0.5 texture ../textures/checker.png 12 12 ]
  ]
  trans [
    translate 0 1 -0.4
    rotate 0 1 0 25
    scale 2 2 2
    object mesh [ file m.obj ambient 0.1 0.1 0.1 diffuse 1 1 1 specular 0.4 0.4 0.4 shine 40
                  texture ../textures/stripes.png 4 2 ]
  ]
  trans [
    translate 0.9 0.35 1.7
    scale 0.9 0.9 0.9
    object mesh [ file m.obj diffuse 0.05 0.05 0.05 specular 0.6 0.6 0.6 shine 80
                  transparent 0.85 0.9 0.95 ior 1.45 ]
  ]
  trans [ rotate 0 1 0 0 subgraph small ]
  trans [ rotate 0 1 0 36 subgraph small_mirror ]
  trans [ rotate 0 1 0 72 subgraph small ]
  trans [ rotate 0 1 0 108 subgraph small_mirror ]
  trans [ rotate 0 1 0 144 subgraph small ]
  trans [ rotate 0 1 0 180 subgraph small_mirror ]
  trans [ rotate 0 1 0 216 subgraph small ]
  trans [ rotate 0 1 0 252 subgraph small_mirror ]
  trans [ rotate 0 1 0 288 subgraph small ]
  trans [ rotate 0 1 0 324 subgraph small_mirror ]
]

mastersubgraph small [
  trans [ translate 3.2 0.05 0 rotate 1 0 0 30 scale 0.8 0.6 0.8
          object mesh [ file m.obj ambient 0.1 0.05 0.02 diffuse 0.85 0.45 0.2 specular 0.3 0.3 0.3 shine 20 ] ]
]

mastersubgraph small_mirror [
  trans [ translate 3.2 0.05 0 scale 0.7 0.7 0.7
          object mesh [ file m.obj diffuse 0.05 0.05 0.1 reflect 0.8 0.8 0.85 specular 0.5 0.5 0.5 shine 60 ] ]
]

===m.obj===
v 0 0 0
v 4 0 0
v 4 4 0
v 2 1 0
v 0 4 0
v 1 2 0
v -1 3 0
f 1 2 3 4 5 6 7
o other
g a b
s 1
usemtl red
mtllib x.mtl
f -7 -6 -5
l 1 2
p 3
