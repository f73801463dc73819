# reflection.sc -- mirror reflection (`reflect r g b`).
#
# Two facing mirror walls produce a corridor of repeated reflections (cut off by
# the recursion depth limit, --max-depth, default 5). In front: a perfect chrome
# sphere (reflect 0.9), a gold-tinted mirror sphere (reflect 0.9 0.7 0.3: coloured
# reflections) and a half-reflective red plastic sphere (diffuse + reflect 0.3).
# The floor is a checker of instanced dark tiles so the reflections have detail.

background [ color 0.4 0.55 0.8 ]

camera [
  eye 1.5 3.2 9
  focus 0 1 0
  up 0 1 0
  angle 45
]

light [ type point position 2 8 6 color 1 1 1 function 1 0 0.005 ]
light [ type directional direction 0.3 -1 -0.2 color 0.3 0.3 0.3 ]

mastersubgraph tile [
  trans [ scale 1 0.02 1 object cube [ ambient 0.02 0.02 0.03 diffuse 0.15 0.15 0.2 ] ]
]

mastersubgraph tilerow [
  trans [ translate -4 0 0 subgraph tile ]
  trans [ translate -2 0 0 subgraph tile ]
  trans [ translate 0 0 0 subgraph tile ]
  trans [ translate 2 0 0 subgraph tile ]
  trans [ translate 4 0 0 subgraph tile ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 40 1 40
    object cube [ ambient 0.1 0.1 0.1 diffuse 0.85 0.85 0.8 ]
  ]
  trans [ translate 0 0.01 -3.5 subgraph tilerow ]
  trans [ translate 1 0.01 -2.5 subgraph tilerow ]
  trans [ translate 0 0.01 -1.5 subgraph tilerow ]
  trans [ translate 1 0.01 -0.5 subgraph tilerow ]
  trans [ translate 0 0.01 0.5 subgraph tilerow ]
  trans [ translate 1 0.01 1.5 subgraph tilerow ]
  trans [ translate 0 0.01 2.5 subgraph tilerow ]
  trans [ translate 1 0.01 3.5 subgraph tilerow ]

  # two parallel mirror walls
  trans [
    translate -5.5 2 0
    scale 0.1 4 9
    object cube [ diffuse 0.03 0.03 0.03 reflect 0.85 0.85 0.85 ]
  ]
  trans [
    translate 5.5 2 0
    scale 0.1 4 9
    object cube [ diffuse 0.03 0.03 0.03 reflect 0.85 0.85 0.85 ]
  ]

  trans [
    translate -2.2 1 0
    scale 2 2 2
    object sphere [ diffuse 0.02 0.02 0.02 specular 1 1 1 shine 200 reflect 0.9 0.9 0.9 ]
  ]
  trans [
    translate 0.4 0.8 1.5
    scale 1.6 1.6 1.6
    object sphere [ ambient 0.02 0.015 0.005 diffuse 0.2 0.15 0.05 specular 1 0.9 0.6 shine 100 reflect 0.9 0.7 0.3 ]
  ]
  trans [
    translate 2.6 0.9 -0.5
    scale 1.8 1.8 1.8
    object sphere [ ambient 0.08 0.01 0.01 diffuse 0.75 0.08 0.06 specular 0.8 0.8 0.8 shine 60 reflect 0.3 0.3 0.3 ]
  ]
]
