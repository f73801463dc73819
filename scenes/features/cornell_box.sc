# cornell_box.sc -- the Cornell box, for the path tracer (scene-format.md §9.2).
#
# Render:  whitted cornell_box.sc --mode path --spp 256
#
# A box of five cubes (white floor, ceiling and back wall, red left wall, green right wall)
# lit only by an emissive panel in the ceiling (`emit`: an area light in path mode), with a
# tall and a short white block inside. Path tracing shows what the Whitted model cannot:
# soft shadows from the panel, red and green light bleeding onto the white surfaces, and the
# ceiling lit by light that bounced off the floor. In Whitted mode the panel only glows and the
# point light below it does the lighting.

camera [
  eye 0 0 3.4
  focus 0 0 0
  angle 40
]

# Only for the Whitted mode (path mode uses it too, by next-event estimation).
light [ position 0 0.8 0.3 color 0.25 0.25 0.25 ]

mastersubgraph root [
  trans [ translate 0 -1.05 0 scale 2.2 0.1 2.2 object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate 0 1.05 0 scale 2.2 0.1 2.2 object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate 0 0 -1.05 scale 2.2 2.2 0.1 object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate -1.05 0 0 scale 0.1 2.2 2.2 object cube [ diffuse 0.63 0.065 0.05 ] ]
  trans [ translate 1.05 0 0 scale 0.1 2.2 2.2 object cube [ diffuse 0.14 0.45 0.091 ] ]
  # The light panel, just below the ceiling.
  trans [ translate 0 0.99 0 scale 0.5 0.02 0.4 object cube [ diffuse 0 0 0 emit 12 11 9 ] ]
  # The blocks.
  trans [ translate -0.35 -0.4 -0.3 rotate 0 1 0 18 scale 0.55 1.2 0.55 object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate 0.38 -0.7 0.25 rotate 0 1 0 -17 scale 0.55 0.6 0.55 object cube [ diffuse 0.73 0.73 0.73 ] ]
]
