# emit_ambient.sc -- light that does not come from light sources.
#
#   emit r g b     the surface glows with this colour everywhere, whatever lights
#                  or shadows there are (it does not light anything else: only
#                  light sources do).
#   ambient r g b  the object's colour under the scene's global ambient intensity
#                  I_a. I_a is 1 1 1 unless a light block sets `ambient`; here one
#                  does (`ambient 0.5 0.5 0.5`), halving every object's ambient term.
# One weak point light is in the scene. Front row, left to right: an emit-only
# "lamp" sphere (diffuse 0), an ambient-only cube (diffuse 0: flat, no shading),
# a normal diffuse cube for comparison, and a cylinder with diffuse AND emit.
# Back: a glowing cone, its foot in the shadow of a low wall, glows evenly all over.

background [ color 0 0 0 ]

camera [
  eye 0 7 10
  focus 0 0.5 -0.6
  up 0 1 0
  angle 45
]

light [ type point position 3 5 5 color 0.7 0.7 0.7 ]
light [ ambient 0.5 0.5 0.5 ]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.1 0.1 0.1 diffuse 0.5 0.5 0.5 ]
  ]
  trans [
    translate -3.3 0.7 2.2
    scale 1.4 1.4 1.4
    object sphere [ diffuse 0 0 0 emit 1 0.85 0.4 ]
  ]
  trans [
    translate -1.1 0.7 2.2
    rotate 0 1 0 30
    scale 1.4 1.4 1.4
    object cube [ diffuse 0 0 0 ambient 0.2 0.6 1 ]
  ]
  trans [
    translate 1.1 0.7 2.2
    rotate 0 1 0 30
    scale 1.4 1.4 1.4
    object cube [ diffuse 0.2 0.6 1 ambient 0.04 0.12 0.2 ]
  ]
  trans [
    translate 3.3 0.7 2.2
    scale 1.2 1.4 1.2
    object cylinder [ diffuse 0.6 0.2 0.2 emit 0.3 0 0.2 ]
  ]
  # a wall casting a shadow over the glowing cone behind it
  trans [
    translate 0 0.5 -1.5
    scale 5 1 0.2
    object cube [ ambient 0.05 0.05 0.05 diffuse 0.6 0.55 0.5 ]
  ]
  trans [
    translate 0 1.2 -2.6
    scale 1.4 2.4 1.4
    object cone [ diffuse 0 0 0 emit 0.2 1 0.4 ]
  ]
]
