# caustic_ball_emissive.sc: caustic_ball.sc lit by an emissive sphere instead of the spotlight (radius
# 0.5, radiance 40, 6 above the glass ball's centre): the variant Cycles can render too
# (bench/caustics_cycles.sh). The floor is lit directly by the sphere and, under the ball, by its caustic.
camera [ eye 0 6 6  focus 0 -3 0  up 0 1 0  angle 30 ]
background [ color 0 0 0 ]
mastersubgraph root [
  trans [ translate 0 6 0  object sphere [ diffuse 0 0 0  emit 40 40 40 ] ]
  trans [ scale 2 2 2  object sphere [ diffuse 0 0 0  transparent 1 1 1  ior 1.5 ] ]
  trans [ translate 0 -3.5 0  scale 40 1 40  object cube [ diffuse 0.8 0.8 0.8 ] ]
]
