# soft_shadows.sc -- area lights: soft shadows from disc lights (scene-format.md §9.1).
#
# Render with several samples per pixel, e.g.  whitted soft_shadows.sc --spp 64
#
# One post, three lights of the same brightness and height: on the left a point light
# (radius 0) casts a hard-edged shadow to the right; behind, a disc of radius 0.5 casts a
# shadow toward the camera whose edge blurs into a penumbra, widest far from the post;
# on the right a disc of radius 1.5 casts a wide penumbra with almost no umbra. With
# one sample per pixel every light is its centre and all three shadows are hard.

background [ color 0.05 0.05 0.07 ]

camera [
  eye 0 7 11
  focus 0 0.5 0
  angle 40
]

light [ position -5 5 0 color 0.35 0.35 0.35 ]
light [ position 0 5 -5 color 0.35 0.35 0.35 radius 0.5 ]
light [ position 5 5 0 color 0.35 0.35 0.35 radius 1.5 ]
light [ ambient 0.5 0.5 0.5 ]

mastersubgraph post [
  trans [
    translate 0 1.25 0
    scale 0.5 2.5 0.5
    object cylinder [ ambient 0.05 0.05 0.05 diffuse 0.8 0.35 0.2 specular 0.3 0.3 0.3 shine 20 ]
  ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.1 0.1 0.1 diffuse 0.85 0.85 0.8 ]
  ]
  trans [ subgraph post ]
]
