# shadows.sc -- hard shadows, including tinted shadows through coloured glass.
#
# One point light (no attenuation) low on the left, so shadows fall to the right. Left: an opaque cube
# and cone cast black-edged hard shadows (only ambient light there). Right: a red
# glass cube and a blue glass sphere cast COLOURED shadows: a shadow ray that crosses
# transparent surfaces is multiplied by their `transparent` colour at each crossing
# (twice for a closed object), so the light reaching the floor is tinted, not
# blocked. Where the two glass shadows overlap, the tints multiply (dark violet).

background [ color 0.1 0.1 0.12 ]

camera [
  eye 0 6 10
  focus 0.5 0.5 -1
  up 0 1 0
  angle 45
]

light [ type point position -7 4.5 2 color 0.9 0.9 0.9 ]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.12 0.12 0.12 diffuse 0.85 0.85 0.85 ]
  ]
  trans [
    translate -3.5 0.6 0
    rotate 0 1 0 25
    scale 1.2 1.2 1.2
    object cube [ ambient 0.06 0.05 0.03 diffuse 0.6 0.5 0.3 ]
  ]
  trans [
    translate -1.5 0.8 -1.5
    scale 1.2 1.6 1.2
    object cone [ ambient 0.03 0.06 0.03 diffuse 0.3 0.6 0.3 ]
  ]
  trans [
    translate 0.8 0.77 0
    rotate 0 1 0 -20
    scale 1.5 1.5 1.5
    object cube [
      diffuse 0 0 0
      specular 1 1 1
      shine 100
      transparent 0.95 0.25 0.2
      ior 1
    ]
  ]
  trans [
    translate 2.4 1 1.6
    scale 2 2 2
    object sphere [
      diffuse 0 0 0
      specular 1 1 1
      shine 100
      transparent 0.3 0.45 1
      ior 1
    ]
  ]
]
