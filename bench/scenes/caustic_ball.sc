# caustic_ball.sc: a glass ball (radius 1, ior 1.5, passing everything) lit by a spotlight whose 5° cone
# covers nothing but the ball, over a white floor: the floor is lit by the caustic alone
# (bench/caustics_povray.sh; caustic_ball.pov is the same scene for POV-Ray 3.7 with photons).
camera [ eye 0 6 6  focus 0 -3 0  up 0 1 0  angle 30 ]
background [ color 0 0 0 ]
light [ type spotlight  position 0 10 0  direction 0 -1 0  aperture 5  exponent 0  color 1 1 1  function 1 0 0 ]
mastersubgraph root [
  trans [ scale 2 2 2  object sphere [ diffuse 0 0 0  transparent 1 1 1  ior 1.5 ] ]
  trans [ translate 0 -3.5 0  scale 40 1 40  object cube [ diffuse 0.8 0.8 0.8 ] ]
]
