# depth_of_field.sc -- a thin-lens camera (scene-format.md §9.1).
#
# Render with several samples per pixel, e.g.  whitted depth_of_field.sc --spp 64
#
# A row of spheres receding from the camera. The lens (aperture 0.4, in world units)
# is focused at the `focus` point, the third sphere: it is sharp, and the spheres in
# front of and behind it blur more the farther they are from the plane in focus (a
# point at distance d is spread over a disc of diameter aperture·|d − F|/d in that
# plane). `focaldistance F` would set the plane without a focus point. With one sample
# per pixel the lens is a pinhole and everything is sharp.

background [ color 0.55 0.65 0.8 ]

camera [
  eye 7 1.8 6
  focus 0 0.5 -2
  angle 48
  aperture 0.4
]

light [ type directional direction -0.5 -1 -0.6 color 0.8 0.8 0.75 ]
light [ ambient 0.4 0.4 0.45 ]

mastersubgraph ball [
  trans [ object sphere [ ambient 0.1 0.1 0.1 diffuse 0.9 0.9 0.9 specular 0.6 0.6 0.6 shine 60 ] ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 40 1 40
    object cube [ ambient 0.08 0.08 0.08 diffuse 0.5 0.55 0.45 ]
  ]
  trans [ translate 1.5 0.5 4 subgraph ball ]
  trans [ translate 0.8 0.5 1 subgraph ball ]
  trans [ translate 0 0.5 -2 subgraph ball ]
  trans [ translate -0.8 0.5 -5 subgraph ball ]
  trans [ translate -1.6 0.5 -8 subgraph ball ]
  trans [ translate -2.4 0.5 -11 subgraph ball ]
]
