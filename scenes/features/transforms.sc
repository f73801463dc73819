# transforms.sc -- how transforms compose.
#
# Back row, right pair: the SAME two transforms (translate 1.5 1.5 -2, rotate 45
# degrees about z) written in the two orders. In one trans block the last transform
# written is applied to the object first.
#   red:   `translate ... rotate ...`: the cube is turned 45 degrees about its own
#          centre, then moved to (1.5, 1.5): a diamond standing at x = 1.5.
#   green: `rotate ... translate ...`: the cube is moved to (1.5, 1.5) first, then
#          the world z axis turns it, so it swings round to (0, 2.12), higher and left.
# Back row, left: a non-uniform scale followed by a rotation about a tilted axis.
# Front row: an asymmetric "L" (mastersubgraph `ell`, red ball on the side of the
#   foot) drawn as is (left), and mirrored by a negative scale (`scale -1 1 1`,
#   second from left): a left-handed copy.
# Far right front: matrixRC and matrixCR giving the same shear (the CR numbers are the
#   RC numbers transposed), so the two violet prisms are identical.

background [ color 0.18 0.2 0.25 ]

camera [
  eye 0 4 11
  focus 0 1.2 0
  up 0 1 0
  angle 45
]

light [ type point position 4 8 8 color 1 1 1 ]
light [ type directional direction 0.2 -1 -0.5 color 0.3 0.3 0.3 ]

mastersubgraph ell [
  trans [ translate 0 0.9 0  scale 0.5 1.8 0.5  object cube [ ambient 0.02 0.04 0.09 diffuse 0.2 0.4 0.9 ] ]
  trans [ translate 0.5 0.25 0  scale 0.5 0.5 0.5  object cube [ ambient 0.02 0.04 0.09 diffuse 0.2 0.4 0.9 ] ]
  trans [ translate 0.25 1.9 0  scale 0.3 0.3 0.3  object sphere [ ambient 0.09 0.02 0.02 diffuse 0.9 0.2 0.2 ] ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.07 0.07 0.07 diffuse 0.7 0.7 0.7 ]
  ]

  # translate, then rotate: turned in place, standing at (1.5, 1.5, -2)
  trans [
    translate 1.5 1.5 -2
    rotate 0 0 1 45
    object cube [ ambient 0.09 0.02 0.02 diffuse 0.9 0.2 0.2 ]
  ]
  # rotate, then translate: the translated cube swings about the origin
  trans [
    rotate 0 0 1 45
    translate 1.5 1.5 -2
    object cube [ ambient 0.02 0.09 0.02 diffuse 0.2 0.9 0.2 ]
  ]
  # a stretched cylinder tipped about a slanted axis
  trans [
    translate -3.5 1.5 -2
    rotate 1 0 1 50
    scale 0.6 2.5 0.6
    object cylinder [ ambient 0.08 0.08 0.02 diffuse 0.85 0.8 0.2 specular 0.5 0.5 0.5 shine 20 ]
  ]

  # mirroring by a negative scale
  trans [ translate -3 0 2  subgraph ell ]
  trans [ translate -1 0 2  scale -1 1 1  subgraph ell ]

  # identical shears, one written row by row, one column by column
  trans [
    translate 1.8 0.75 2
    matrixRC 1 0.5 0 0
             0 1   0 0
             0 0   1 0
             0 0   0 1
    scale 0.8 1.5 0.8
    object cube [ ambient 0.06 0.02 0.09 diffuse 0.6 0.2 0.9 ]
  ]
  trans [
    translate 3.8 0.75 2
    matrixCR 1   0 0 0
             0.5 1 0 0
             0   0 1 0
             0   0 0 1
    scale 0.8 1.5 0.8
    object cube [ ambient 0.06 0.02 0.09 diffuse 0.6 0.2 0.9 ]
  ]
]
