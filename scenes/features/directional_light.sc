# directional_light.sc -- a directional light (like the sun).
#
# `direction` is the way the light travels; it has no position and no attenuation,
# so every surface facing it the same way is equally bright however far away, and
# all shadows are parallel (the posts' shadows below do not fan out as they would
# under a point light). The only other light is the objects' ambient term.

background [ color 0.5 0.65 0.85 ]

camera [
  eye 0 7 12
  focus 0 0 -1
  up 0 1 0
  angle 45
]

light [
  type directional
  direction -1 -1.2 -0.6
  color 1 0.95 0.85
]

mastersubgraph post [
  trans [ translate 0 1 0 scale 0.35 2 0.35 object cylinder [ ambient 0.1 0.05 0.03 diffuse 0.7 0.4 0.25 ] ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.12 0.12 0.1 diffuse 0.75 0.75 0.7 ]
  ]
  trans [ translate -4 0 -4 subgraph post ]
  trans [ translate -1 0 -4 subgraph post ]
  trans [ translate 2 0 -4 subgraph post ]
  trans [ translate 5 0 -4 subgraph post ]
  trans [ translate -4 0 1 subgraph post ]
  trans [ translate -1 0 1 subgraph post ]
  trans [ translate 2 0 1 subgraph post ]
  trans [ translate 5 0 1 subgraph post ]
  trans [
    translate 0 0.8 3.5
    scale 1.6 1.6 1.6
    object sphere [ ambient 0.02 0.06 0.1 diffuse 0.2 0.5 0.9 specular 0.6 0.6 0.6 shine 40 ]
  ]
]
