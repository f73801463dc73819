# glossy.sc -- glossy reflection and frosted glass (scene-format.md §9.1).
#
# Render with several samples per pixel, e.g.  whitted glossy.sc --spp 64
#
# `gloss e` draws the reflected and refracted rays from a cos^e lobe around the ideal
# direction, as `shine` shapes a highlight. Back row, mirrors from sharp to rough:
# no gloss (an ideal mirror), gloss 1000 (polished metal), 100, and 10 (brushed).
# Front: clear glass and frosted glass (gloss 50) over a striped floor. With one sample
# per pixel every ray takes its ideal direction.

background [ color 0.2 0.22 0.28 ]

camera [
  eye 0 3.2 8
  focus 0 1 0
  angle 45
]

light [ position 3 8 6 color 0.7 0.7 0.7 ]
light [ position -6 5 3 color 0.3 0.3 0.35 ]
light [ ambient 0.6 0.6 0.6 ]

mastersubgraph stripe [
  trans [ scale 0.5 0.02 20 object cube [ ambient 0.02 0.02 0.02 diffuse 0.1 0.1 0.12 ] ]
]

mastersubgraph root [
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [ ambient 0.1 0.1 0.1 diffuse 0.85 0.8 0.7 ]
  ]
  trans [ translate -3 0.01 0 subgraph stripe ]
  trans [ translate -1 0.01 0 subgraph stripe ]
  trans [ translate 1 0.01 0 subgraph stripe ]
  trans [ translate 3 0.01 0 subgraph stripe ]
  trans [ translate -3.3 1 -2 object sphere [ diffuse 0.05 0.05 0.05 specular 1 1 1 shine 200 reflect 0.85 0.85 0.85 ] ]
  trans [ translate -1.1 1 -2 object sphere [ diffuse 0.05 0.05 0.05 specular 1 1 1 shine 200 reflect 0.85 0.85 0.85 gloss 1000 ] ]
  trans [ translate 1.1 1 -2 object sphere [ diffuse 0.05 0.05 0.05 specular 1 1 1 shine 100 reflect 0.85 0.85 0.85 gloss 100 ] ]
  trans [ translate 3.3 1 -2 object sphere [ diffuse 0.05 0.05 0.05 specular 1 1 1 shine 30 reflect 0.85 0.85 0.85 gloss 10 ] ]
  trans [ translate -1.2 0.8 1.5 scale 1.6 1.6 1.6 object sphere [ diffuse 0 0 0 specular 1 1 1 shine 150 transparent 0.9 0.9 0.9 ior 1.5 ] ]
  trans [ translate 1.2 0.8 1.5 scale 1.6 1.6 1.6 object sphere [ diffuse 0 0 0 specular 1 1 1 shine 150 transparent 0.9 0.9 0.9 ior 1.5 gloss 50 ] ]
]
