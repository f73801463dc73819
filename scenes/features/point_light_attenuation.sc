# point_light_attenuation.sc -- point lights with distance attenuation.
#
# att = 1 / (c + l*d + q*d^2) for `function c l q`, d = distance to the light.
# Two rows of identical white spheres run away from the camera, each row lit by its
# own point light hanging over its near end:
#   left row:  function 1 0 0      -- no attenuation: the far spheres are as bright
#                                     as the near ones (only the angle changes).
#   right row: function 0.2 0 0.12 -- quadratic falloff: bright at the light, dim
#                                     at the far end (the light colour is above 1,
#                                     which is legal: it is an intensity).
# A low wall between the rows keeps each light on its own side.

background [ color 0 0 0 ]

camera [
  eye 0 6 9
  focus 0 0 -4
  up 0 1 0
  angle 50
]

light [ type point position -2.5 2.5 3 color 0.8 0.8 0.8 function 1 0 0 ]
light [ type point position 2.5 2.5 3 color 3 3 3 function 0.2 0 0.12 ]

mastersubgraph ball [
  trans [ translate 0 0.5 0  object sphere [ ambient 0.02 0.02 0.02 diffuse 0.9 0.9 0.9 ] ]
]

mastersubgraph row [
  trans [ translate 0 0 2 subgraph ball ]
  trans [ translate 0 0 0 subgraph ball ]
  trans [ translate 0 0 -2 subgraph ball ]
  trans [ translate 0 0 -4 subgraph ball ]
  trans [ translate 0 0 -6 subgraph ball ]
  trans [ translate 0 0 -8 subgraph ball ]
  trans [ translate 0 0 -10 subgraph ball ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 -4
    scale 12 1 20
    object cube [ ambient 0.02 0.02 0.02 diffuse 0.6 0.6 0.6 ]
  ]
  trans [
    translate 0 0.6 -4
    scale 0.2 1.2 20
    object cube [ ambient 0.03 0.03 0.03 diffuse 0.5 0.4 0.3 ]
  ]
  trans [ translate -2.5 0 0 subgraph row ]
  trans [ translate 2.5 0 0 subgraph row ]
]
