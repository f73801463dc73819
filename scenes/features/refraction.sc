# refraction.sc -- refraction through glass (`transparent` + `ior`).
#
# A wall-sized checker of small cubes (instanced) stands behind three glass objects:
#   centre: a glass sphere (ior 1.5): the checker appears upside down and shrunk
#           through it, like through a lens.
#   left:   a glass cube turned 40 degrees (ior 1.5): its side faces shift the checker
#           sideways, and near its edges rays are totally internally reflected, so
#           some facets show the floor or the other faces instead of the wall.
#   right:  a "diamond" sphere (ior 2.4): strong total internal reflection makes
#           its rim a bright mirror-like ring.
# On total internal reflection a single reflected ray carries reflect + transparent.

background [ color 0.05 0.05 0.08 ]

camera [
  eye 0 2.2 9
  focus 0 1.6 0
  up 0 1 0
  angle 44
]

light [ type point position 0 6 8 color 1 1 1 ]
light [ type directional direction 0.2 -0.5 -1 color 0.4 0.4 0.4 ]

# One checker row: 8 alternating white and red cubes, each 0.5 wide.
mastersubgraph checkrow [
  trans [ translate -1.75 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.1 0.1 0.1 diffuse 0.9 0.9 0.9 ] ]
  trans [ translate -1.25 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.08 0.01 0.01 diffuse 0.8 0.1 0.1 ] ]
  trans [ translate -0.75 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.1 0.1 0.1 diffuse 0.9 0.9 0.9 ] ]
  trans [ translate -0.25 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.08 0.01 0.01 diffuse 0.8 0.1 0.1 ] ]
  trans [ translate 0.25 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.1 0.1 0.1 diffuse 0.9 0.9 0.9 ] ]
  trans [ translate 0.75 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.08 0.01 0.01 diffuse 0.8 0.1 0.1 ] ]
  trans [ translate 1.25 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.1 0.1 0.1 diffuse 0.9 0.9 0.9 ] ]
  trans [ translate 1.75 0 0 scale 0.5 0.5 0.3 object cube [ ambient 0.08 0.01 0.01 diffuse 0.8 0.1 0.1 ] ]
]

# Two rows, the second shifted by one cube: a 4 x 1 wall piece of checker.
mastersubgraph checkpair [
  trans [ translate 0 0 0 subgraph checkrow ]
  trans [ translate 0 0.5 0 scale -1 1 1 subgraph checkrow ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.06 0.06 0.07 diffuse 0.5 0.5 0.55 ]
  ]
  # the checker wall: 2 x 4 pieces of 4 x 1 = 8 wide, 4 high, at z = -3
  trans [ translate -2 0.25 -3 subgraph checkpair ]
  trans [ translate -2 1.25 -3 subgraph checkpair ]
  trans [ translate -2 2.25 -3 subgraph checkpair ]
  trans [ translate -2 3.25 -3 subgraph checkpair ]
  trans [ translate 2 0.25 -3 subgraph checkpair ]
  trans [ translate 2 1.25 -3 subgraph checkpair ]
  trans [ translate 2 2.25 -3 subgraph checkpair ]
  trans [ translate 2 3.25 -3 subgraph checkpair ]

  trans [
    translate 0 1.3 1
    scale 2.2 2.2 2.2
    object sphere [ diffuse 0 0 0 specular 1 1 1 shine 150 reflect 0.05 0.05 0.05 transparent 0.95 0.95 0.95 ior 1.5 ]
  ]
  trans [
    translate -2.5 0.87 1.2
    rotate 0 1 0 40
    rotate 1 0 0 15
    scale 1.4 1.4 1.4
    object cube [ diffuse 0 0 0 specular 1 1 1 shine 150 reflect 0.05 0.05 0.05 transparent 0.95 0.95 0.95 ior 1.5 ]
  ]
  trans [
    translate 2.6 0.75 1.4
    scale 1.5 1.5 1.5
    object sphere [ diffuse 0 0 0 specular 1 1 1 shine 300 reflect 0.05 0.05 0.05 transparent 0.95 0.95 0.95 ior 2.4 ]
  ]
]
