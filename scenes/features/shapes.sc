# shapes.sc -- the four primitive shapes side by side, all unit size.
# Left to right: cube, cylinder (axis +Y, capped), cone (apex up, capped base), sphere.
# Each is the unit object ([-0.5, 0.5]^3) scaled by 1.6, standing on the floor,
# lit by one point light and a weak directional light so every shape shows
# its top, its side and its shadow.

background [ color 0.2 0.22 0.28 ]

camera [
  eye 0 3.4 10
  focus 0 0.7 0
  up 0 1 0
  angle 40
]

light [
  type point
  position 3 6 5
  color 1 1 1
]

light [
  type directional
  direction -0.3 -1 -0.4
  color 0.25 0.25 0.25
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 20 1 20
    object cube [ ambient 0.08 0.08 0.08 diffuse 0.7 0.7 0.7 ]
  ]
  trans [
    translate -3.3 0.8 0
    scale 1.6 1.6 1.6
    object cube [ ambient 0.09 0.02 0.02 diffuse 0.9 0.2 0.2 specular 0.5 0.5 0.5 shine 30 ]
  ]
  trans [
    translate -1.1 0.8 0
    scale 1.6 1.6 1.6
    object cylinder [ ambient 0.02 0.09 0.02 diffuse 0.2 0.85 0.25 specular 0.5 0.5 0.5 shine 30 ]
  ]
  trans [
    translate 1.1 0.8 0
    scale 1.6 1.6 1.6
    object cone [ ambient 0.02 0.04 0.09 diffuse 0.2 0.4 0.9 specular 0.5 0.5 0.5 shine 30 ]
  ]
  trans [
    translate 3.3 0.8 0
    scale 1.6 1.6 1.6
    object sphere [ ambient 0.09 0.08 0.02 diffuse 0.9 0.8 0.2 specular 0.5 0.5 0.5 shine 30 ]
  ]
]
