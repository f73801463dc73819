# effects.sc -- the §9.1 effects for whitted-mpi's --spp test: a disc light (radius 0.5), a thin-lens
# camera (aperture, focaldistance) and a glossy sphere, from scenes/features/shadows.sc.
#
# Soft shadows of the cube, cone and glass; the focal plane near the glass cube, the rest blurred.

background [ color 0.1 0.1 0.12 ]

camera [
  eye 0 6 10
  focus 0.5 0.5 -1
  up 0 1 0
  angle 45
  aperture 0.3
  focaldistance 9
]

light [ type point position -7 4.5 2 color 0.9 0.9 0.9 radius 0.5 ]

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
      gloss 40
      ior 1
    ]
  ]
]
