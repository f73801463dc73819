# spotlight.sc -- spotlights: aperture (cone half-angle) and exponent (falloff).
#
# Intensity is multiplied by cos(theta)^exponent inside the cone (theta <= aperture)
# and is 0 outside it. Three spotlights hang at the same height over a grey floor,
# pointing straight down, each over a white sphere:
#   left:   aperture 20, exponent 0   -- a hard-edged disc of uniform light
#   middle: aperture 35, exponent 1   -- a wider disc, slightly darker at its rim
#   right:  aperture 35, exponent 60  -- a soft hot spot that fades out well before
#                                       the 35-degree edge of its cone
# The left light is red, the middle green and the right blue, so the pools of light
# can be told apart; all have gentle quadratic attenuation.

background [ color 0 0 0 ]

camera [
  eye 0 7 10
  focus 0 0 -0.5
  up 0 1 0
  angle 50
]

light [ type spotlight position -5 4 0 direction 0 -1 0 color 1.2 0.35 0.3 function 1 0 0.004 aperture 20 exponent 0 ]
light [ type spotlight position 0 4 0 direction 0 -1 0 color 0.35 1.2 0.35 function 1 0 0.004 aperture 35 exponent 1 ]
light [ type spotlight position 5 4 0 direction 0 -1 0 color 0.35 0.45 1.4 function 1 0 0.004 aperture 35 exponent 60 ]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.03 0.03 0.03 diffuse 0.8 0.8 0.8 ]
  ]
  trans [ translate -5 0.5 0 object sphere [ diffuse 0.9 0.9 0.9 specular 0.5 0.5 0.5 shine 30 ] ]
  trans [ translate 0 0.5 0 object sphere [ diffuse 0.9 0.9 0.9 specular 0.5 0.5 0.5 shine 30 ] ]
  trans [ translate 5 0.5 0 object sphere [ diffuse 0.9 0.9 0.9 specular 0.5 0.5 0.5 shine 30 ] ]
]
