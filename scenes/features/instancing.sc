# instancing.sc -- reusing a mastersubgraph many times (`subgraph NAME`).
#
# `root` places a ring of `tree`s, and does so BEFORE `tree` is defined in this file
# (a forward reference: allowed in whitted; the original labs required
# define-before-use). `tree` itself instantiates `crown` twice, so instancing nests:
# root -> tree -> crown. Every instance gets its trans block's matrix, so trees can
# be moved, turned, and scaled non-uniformly (the tall thin tree at the back, the
# squat wide one in front). 9 trees x (1 trunk + 2 x 2 crown parts) = 45 objects
# from 5 object definitions.

background [ color 0.55 0.7 0.9 ]

camera [
  eye 0 6 11
  focus 0 1 0
  up 0 1 0
  angle 45
]

light [ type point position 5 10 6 color 1 1 0.95 function 1 0 0.002 ]
light [ type directional direction -0.5 -1 -0.3 color 0.3 0.3 0.35 ]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.05 0.08 0.03 diffuse 0.4 0.65 0.3 ]
  ]
  trans [ translate 0 0 0 subgraph tree ]
  trans [ translate 3 0 0 rotate 0 1 0 30 subgraph tree ]
  trans [ translate -3 0 0 rotate 0 1 0 60 subgraph tree ]
  trans [ translate 2.1 0 -2.1 subgraph tree ]
  trans [ translate -2.1 0 -2.1 subgraph tree ]
  trans [ translate 0 0 -3 scale 0.7 1.8 0.7 subgraph tree ]
  trans [ translate 2.1 0 2.1 scale 0.8 0.8 0.8 subgraph tree ]
  trans [ translate -2.1 0 2.1 scale 0.8 0.8 0.8 subgraph tree ]
  trans [ translate 0 0 3 scale 1.5 0.7 1.5 subgraph tree ]
]

mastersubgraph tree [
  trans [
    translate 0 0.6 0
    scale 0.25 1.2 0.25
    object cylinder [ ambient 0.05 0.03 0.01 diffuse 0.45 0.28 0.12 ]
  ]
  trans [ translate 0 1.3 0 subgraph crown ]
  trans [ translate 0 1.9 0 scale 0.7 0.8 0.7 subgraph crown ]
]

mastersubgraph crown [
  trans [
    translate 0 0.35 0
    scale 1.2 0.9 1.2
    object cone [ ambient 0.01 0.06 0.02 diffuse 0.1 0.5 0.15 specular 0.2 0.2 0.2 shine 10 ]
  ]
  trans [
    translate 0 0.95 0
    scale 0.18 0.18 0.18
    object sphere [ ambient 0.1 0.08 0.01 diffuse 0.95 0.8 0.1 specular 0.8 0.8 0.8 shine 50 ]
  ]
]
