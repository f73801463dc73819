# 10000 objects: a 100 x 100 grid, written by bench/gen_scene
camera [ eye 0 45 85  focus 0 0 -5  up 0 1 0  angle 50 ]
background [ color 0.5 0.65 0.85 ]
light [ type point  position 30 200 40  color 0.8 0.8 0.8 ]
light [ type directional  direction -0.3 -1 -0.5  color 0.3 0.3 0.3 ]
light [ ambient 0.2 0.2 0.2 ]

mastersubgraph block [
  trans [ translate 0.5 0.25 0.5  rotate 1 1 0 0  scale 0.5 0.5 0.5
    object cube [ diffuse 0.3 0.3 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.275 1.5  rotate 1 1 0 37  scale 0.54 0.55 0.53
    object cylinder [ diffuse 0.37 0.36 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.3 2.5  rotate 1 1 0 74  scale 0.58 0.6 0.56
    object cone [ diffuse 0.44 0.42 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.325 3.5  rotate 1 1 0 21  scale 0.62 0.65 0.59
    object sphere [ diffuse 0.51 0.48 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 0.5 0.35 4.5  rotate 1 1 0 58  scale 0.66 0.7 0.62
    object cube [ diffuse 0.58 0.54 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.25 5.5  rotate 1 1 0 5  scale 0.7 0.5 0.65
    object cylinder [ diffuse 0.65 0.6 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.275 6.5  rotate 1 1 0 42  scale 0.74 0.55 0.68
    object cone [ diffuse 0.72 0.66 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.3 7.5  rotate 1 1 0 79  scale 0.5 0.6 0.71
    object sphere [ diffuse 0.79 0.72 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.325 8.5  rotate 1 1 0 26  scale 0.54 0.65 0.74
    object cube [ diffuse 0.86 0.78 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 0.5 0.35 9.5  rotate 1 1 0 63  scale 0.58 0.7 0.5
    object cylinder [ diffuse 0.93 0.84 0.45  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.25 0.5  rotate 1 1 0 10  scale 0.62 0.5 0.53
    object cylinder [ diffuse 0.3 0.9 0.4  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.275 1.5  rotate 1 1 0 47  scale 0.66 0.55 0.56
    object cone [ diffuse 0.37 0.3 0.35  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.3 2.5  rotate 1 1 0 84  scale 0.7 0.6 0.59
    object sphere [ diffuse 0.44 0.36 0.3  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.325 3.5  rotate 1 1 0 31  scale 0.74 0.65 0.62
    object cube [ diffuse 0.51 0.42 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 1.5 0.35 4.5  rotate 1 1 0 68  scale 0.5 0.7 0.65
    object cylinder [ diffuse 0.58 0.48 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.25 5.5  rotate 1 1 0 15  scale 0.54 0.5 0.68
    object cone [ diffuse 0.65 0.54 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.275 6.5  rotate 1 1 0 52  scale 0.58 0.55 0.71
    object sphere [ diffuse 0.72 0.6 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.3 7.5  rotate 1 1 0 89  scale 0.62 0.6 0.74
    object cube [ diffuse 0.79 0.66 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.325 8.5  rotate 1 1 0 36  scale 0.66 0.65 0.5
    object cylinder [ diffuse 0.86 0.72 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 1.5 0.35 9.5  rotate 1 1 0 73  scale 0.7 0.7 0.53
    object cone [ diffuse 0.93 0.78 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.25 0.5  rotate 1 1 0 20  scale 0.74 0.5 0.56
    object cone [ diffuse 0.3 0.84 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.275 1.5  rotate 1 1 0 57  scale 0.5 0.55 0.59
    object sphere [ diffuse 0.37 0.9 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.3 2.5  rotate 1 1 0 4  scale 0.54 0.6 0.62
    object cube [ diffuse 0.44 0.3 0.45  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.325 3.5  rotate 1 1 0 41  scale 0.58 0.65 0.65
    object cylinder [ diffuse 0.51 0.36 0.4  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 2.5 0.35 4.5  rotate 1 1 0 78  scale 0.62 0.7 0.68
    object cone [ diffuse 0.58 0.42 0.35  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.25 5.5  rotate 1 1 0 25  scale 0.66 0.5 0.71
    object sphere [ diffuse 0.65 0.48 0.3  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.275 6.5  rotate 1 1 0 62  scale 0.7 0.55 0.74
    object cube [ diffuse 0.72 0.54 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.3 7.5  rotate 1 1 0 9  scale 0.74 0.6 0.5
    object cylinder [ diffuse 0.79 0.6 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.325 8.5  rotate 1 1 0 46  scale 0.5 0.65 0.53
    object cone [ diffuse 0.86 0.66 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 2.5 0.35 9.5  rotate 1 1 0 83  scale 0.54 0.7 0.56
    object sphere [ diffuse 0.93 0.72 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.25 0.5  rotate 1 1 0 30  scale 0.58 0.5 0.59
    object sphere [ diffuse 0.3 0.78 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.275 1.5  rotate 1 1 0 67  scale 0.62 0.55 0.62
    object cube [ diffuse 0.37 0.84 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.3 2.5  rotate 1 1 0 14  scale 0.66 0.6 0.65
    object cylinder [ diffuse 0.44 0.9 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.325 3.5  rotate 1 1 0 51  scale 0.7 0.65 0.68
    object cone [ diffuse 0.51 0.3 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 3.5 0.35 4.5  rotate 1 1 0 88  scale 0.74 0.7 0.71
    object sphere [ diffuse 0.58 0.36 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.25 5.5  rotate 1 1 0 35  scale 0.5 0.5 0.74
    object cube [ diffuse 0.65 0.42 0.45  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.275 6.5  rotate 1 1 0 72  scale 0.54 0.55 0.5
    object cylinder [ diffuse 0.72 0.48 0.4  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.3 7.5  rotate 1 1 0 19  scale 0.58 0.6 0.53
    object cone [ diffuse 0.79 0.54 0.35  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.325 8.5  rotate 1 1 0 56  scale 0.62 0.65 0.56
    object sphere [ diffuse 0.86 0.6 0.3  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 3.5 0.35 9.5  rotate 1 1 0 3  scale 0.66 0.7 0.59
    object cube [ diffuse 0.93 0.66 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.25 0.5  rotate 1 1 0 40  scale 0.7 0.5 0.62
    object cube [ diffuse 0.3 0.72 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.275 1.5  rotate 1 1 0 77  scale 0.74 0.55 0.65
    object cylinder [ diffuse 0.37 0.78 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.3 2.5  rotate 1 1 0 24  scale 0.5 0.6 0.68
    object cone [ diffuse 0.44 0.84 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.325 3.5  rotate 1 1 0 61  scale 0.54 0.65 0.71
    object sphere [ diffuse 0.51 0.9 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 4.5 0.35 4.5  rotate 1 1 0 8  scale 0.58 0.7 0.74
    object cube [ diffuse 0.58 0.3 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.25 5.5  rotate 1 1 0 45  scale 0.62 0.5 0.5
    object cylinder [ diffuse 0.65 0.36 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.275 6.5  rotate 1 1 0 82  scale 0.66 0.55 0.53
    object cone [ diffuse 0.72 0.42 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.3 7.5  rotate 1 1 0 29  scale 0.7 0.6 0.56
    object sphere [ diffuse 0.79 0.48 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.325 8.5  rotate 1 1 0 66  scale 0.74 0.65 0.59
    object cube [ diffuse 0.86 0.54 0.45  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 4.5 0.35 9.5  rotate 1 1 0 13  scale 0.5 0.7 0.62
    object cylinder [ diffuse 0.93 0.6 0.4  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.25 0.5  rotate 1 1 0 50  scale 0.54 0.5 0.65
    object cylinder [ diffuse 0.3 0.66 0.35  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.275 1.5  rotate 1 1 0 87  scale 0.58 0.55 0.68
    object cone [ diffuse 0.37 0.72 0.3  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.3 2.5  rotate 1 1 0 34  scale 0.62 0.6 0.71
    object sphere [ diffuse 0.44 0.78 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.325 3.5  rotate 1 1 0 71  scale 0.66 0.65 0.74
    object cube [ diffuse 0.51 0.84 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 5.5 0.35 4.5  rotate 1 1 0 18  scale 0.7 0.7 0.5
    object cylinder [ diffuse 0.58 0.9 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.25 5.5  rotate 1 1 0 55  scale 0.74 0.5 0.53
    object cone [ diffuse 0.65 0.3 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.275 6.5  rotate 1 1 0 2  scale 0.5 0.55 0.56
    object sphere [ diffuse 0.72 0.36 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.3 7.5  rotate 1 1 0 39  scale 0.54 0.6 0.59
    object cube [ diffuse 0.79 0.42 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.325 8.5  rotate 1 1 0 76  scale 0.58 0.65 0.62
    object cylinder [ diffuse 0.86 0.48 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 5.5 0.35 9.5  rotate 1 1 0 23  scale 0.62 0.7 0.65
    object cone [ diffuse 0.93 0.54 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.25 0.5  rotate 1 1 0 60  scale 0.66 0.5 0.68
    object cone [ diffuse 0.3 0.6 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.275 1.5  rotate 1 1 0 7  scale 0.7 0.55 0.71
    object sphere [ diffuse 0.37 0.66 0.45  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.3 2.5  rotate 1 1 0 44  scale 0.74 0.6 0.74
    object cube [ diffuse 0.44 0.72 0.4  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.325 3.5  rotate 1 1 0 81  scale 0.5 0.65 0.5
    object cylinder [ diffuse 0.51 0.78 0.35  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 6.5 0.35 4.5  rotate 1 1 0 28  scale 0.54 0.7 0.53
    object cone [ diffuse 0.58 0.84 0.3  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.25 5.5  rotate 1 1 0 65  scale 0.58 0.5 0.56
    object sphere [ diffuse 0.65 0.9 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.275 6.5  rotate 1 1 0 12  scale 0.62 0.55 0.59
    object cube [ diffuse 0.72 0.3 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.3 7.5  rotate 1 1 0 49  scale 0.66 0.6 0.62
    object cylinder [ diffuse 0.79 0.36 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.325 8.5  rotate 1 1 0 86  scale 0.7 0.65 0.65
    object cone [ diffuse 0.86 0.42 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 6.5 0.35 9.5  rotate 1 1 0 33  scale 0.74 0.7 0.68
    object sphere [ diffuse 0.93 0.48 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.25 0.5  rotate 1 1 0 70  scale 0.5 0.5 0.71
    object sphere [ diffuse 0.3 0.54 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.275 1.5  rotate 1 1 0 17  scale 0.54 0.55 0.74
    object cube [ diffuse 0.37 0.6 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.3 2.5  rotate 1 1 0 54  scale 0.58 0.6 0.5
    object cylinder [ diffuse 0.44 0.66 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.325 3.5  rotate 1 1 0 1  scale 0.62 0.65 0.53
    object cone [ diffuse 0.51 0.72 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 7.5 0.35 4.5  rotate 1 1 0 38  scale 0.66 0.7 0.56
    object sphere [ diffuse 0.58 0.78 0.45  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.25 5.5  rotate 1 1 0 75  scale 0.7 0.5 0.59
    object cube [ diffuse 0.65 0.84 0.4  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.275 6.5  rotate 1 1 0 22  scale 0.74 0.55 0.62
    object cylinder [ diffuse 0.72 0.9 0.35  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.3 7.5  rotate 1 1 0 59  scale 0.5 0.6 0.65
    object cone [ diffuse 0.79 0.3 0.3  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.325 8.5  rotate 1 1 0 6  scale 0.54 0.65 0.68
    object sphere [ diffuse 0.86 0.36 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 7.5 0.35 9.5  rotate 1 1 0 43  scale 0.58 0.7 0.71
    object cube [ diffuse 0.93 0.42 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.25 0.5  rotate 1 1 0 80  scale 0.62 0.5 0.74
    object cube [ diffuse 0.3 0.48 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.275 1.5  rotate 1 1 0 27  scale 0.66 0.55 0.5
    object cylinder [ diffuse 0.37 0.54 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.3 2.5  rotate 1 1 0 64  scale 0.7 0.6 0.53
    object cone [ diffuse 0.44 0.6 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.325 3.5  rotate 1 1 0 11  scale 0.74 0.65 0.56
    object sphere [ diffuse 0.51 0.66 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 8.5 0.35 4.5  rotate 1 1 0 48  scale 0.5 0.7 0.59
    object cube [ diffuse 0.58 0.72 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.25 5.5  rotate 1 1 0 85  scale 0.54 0.5 0.62
    object cylinder [ diffuse 0.65 0.78 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.275 6.5  rotate 1 1 0 32  scale 0.58 0.55 0.65
    object cone [ diffuse 0.72 0.84 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.3 7.5  rotate 1 1 0 69  scale 0.62 0.6 0.68
    object sphere [ diffuse 0.79 0.9 0.45  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.325 8.5  rotate 1 1 0 16  scale 0.66 0.65 0.71
    object cube [ diffuse 0.86 0.3 0.4  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 8.5 0.35 9.5  rotate 1 1 0 53  scale 0.7 0.7 0.74
    object cylinder [ diffuse 0.93 0.36 0.35  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.25 0.5  rotate 1 1 0 0  scale 0.74 0.5 0.5
    object cylinder [ diffuse 0.3 0.42 0.3  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.275 1.5  rotate 1 1 0 37  scale 0.5 0.55 0.53
    object cone [ diffuse 0.37 0.48 0.9  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.3 2.5  rotate 1 1 0 74  scale 0.54 0.6 0.56
    object sphere [ diffuse 0.44 0.54 0.85  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.325 3.5  rotate 1 1 0 21  scale 0.58 0.65 0.59
    object cube [ diffuse 0.51 0.6 0.8  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30  reflect 0.5 0.5 0.5 ] ]
  trans [ translate 9.5 0.35 4.5  rotate 1 1 0 58  scale 0.62 0.7 0.62
    object cylinder [ diffuse 0.58 0.66 0.75  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.25 5.5  rotate 1 1 0 5  scale 0.66 0.5 0.65
    object cone [ diffuse 0.65 0.72 0.7  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.275 6.5  rotate 1 1 0 42  scale 0.7 0.55 0.68
    object sphere [ diffuse 0.72 0.78 0.65  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.3 7.5  rotate 1 1 0 79  scale 0.74 0.6 0.71
    object cube [ diffuse 0.79 0.84 0.6  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.325 8.5  rotate 1 1 0 26  scale 0.5 0.65 0.74
    object cylinder [ diffuse 0.86 0.9 0.55  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
  trans [ translate 9.5 0.35 9.5  rotate 1 1 0 63  scale 0.54 0.7 0.5
    object cone [ diffuse 0.93 0.3 0.5  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30 ] ]
]

mastersubgraph root [
  trans [ translate -50 0 -50 subgraph block ]
  trans [ translate -50 0 -40 subgraph block ]
  trans [ translate -50 0 -30 subgraph block ]
  trans [ translate -50 0 -20 subgraph block ]
  trans [ translate -50 0 -10 subgraph block ]
  trans [ translate -50 0 0 subgraph block ]
  trans [ translate -50 0 10 subgraph block ]
  trans [ translate -50 0 20 subgraph block ]
  trans [ translate -50 0 30 subgraph block ]
  trans [ translate -50 0 40 subgraph block ]
  trans [ translate -40 0 -50 subgraph block ]
  trans [ translate -40 0 -40 subgraph block ]
  trans [ translate -40 0 -30 subgraph block ]
  trans [ translate -40 0 -20 subgraph block ]
  trans [ translate -40 0 -10 subgraph block ]
  trans [ translate -40 0 0 subgraph block ]
  trans [ translate -40 0 10 subgraph block ]
  trans [ translate -40 0 20 subgraph block ]
  trans [ translate -40 0 30 subgraph block ]
  trans [ translate -40 0 40 subgraph block ]
  trans [ translate -30 0 -50 subgraph block ]
  trans [ translate -30 0 -40 subgraph block ]
  trans [ translate -30 0 -30 subgraph block ]
  trans [ translate -30 0 -20 subgraph block ]
  trans [ translate -30 0 -10 subgraph block ]
  trans [ translate -30 0 0 subgraph block ]
  trans [ translate -30 0 10 subgraph block ]
  trans [ translate -30 0 20 subgraph block ]
  trans [ translate -30 0 30 subgraph block ]
  trans [ translate -30 0 40 subgraph block ]
  trans [ translate -20 0 -50 subgraph block ]
  trans [ translate -20 0 -40 subgraph block ]
  trans [ translate -20 0 -30 subgraph block ]
  trans [ translate -20 0 -20 subgraph block ]
  trans [ translate -20 0 -10 subgraph block ]
  trans [ translate -20 0 0 subgraph block ]
  trans [ translate -20 0 10 subgraph block ]
  trans [ translate -20 0 20 subgraph block ]
  trans [ translate -20 0 30 subgraph block ]
  trans [ translate -20 0 40 subgraph block ]
  trans [ translate -10 0 -50 subgraph block ]
  trans [ translate -10 0 -40 subgraph block ]
  trans [ translate -10 0 -30 subgraph block ]
  trans [ translate -10 0 -20 subgraph block ]
  trans [ translate -10 0 -10 subgraph block ]
  trans [ translate -10 0 0 subgraph block ]
  trans [ translate -10 0 10 subgraph block ]
  trans [ translate -10 0 20 subgraph block ]
  trans [ translate -10 0 30 subgraph block ]
  trans [ translate -10 0 40 subgraph block ]
  trans [ translate 0 0 -50 subgraph block ]
  trans [ translate 0 0 -40 subgraph block ]
  trans [ translate 0 0 -30 subgraph block ]
  trans [ translate 0 0 -20 subgraph block ]
  trans [ translate 0 0 -10 subgraph block ]
  trans [ translate 0 0 0 subgraph block ]
  trans [ translate 0 0 10 subgraph block ]
  trans [ translate 0 0 20 subgraph block ]
  trans [ translate 0 0 30 subgraph block ]
  trans [ translate 0 0 40 subgraph block ]
  trans [ translate 10 0 -50 subgraph block ]
  trans [ translate 10 0 -40 subgraph block ]
  trans [ translate 10 0 -30 subgraph block ]
  trans [ translate 10 0 -20 subgraph block ]
  trans [ translate 10 0 -10 subgraph block ]
  trans [ translate 10 0 0 subgraph block ]
  trans [ translate 10 0 10 subgraph block ]
  trans [ translate 10 0 20 subgraph block ]
  trans [ translate 10 0 30 subgraph block ]
  trans [ translate 10 0 40 subgraph block ]
  trans [ translate 20 0 -50 subgraph block ]
  trans [ translate 20 0 -40 subgraph block ]
  trans [ translate 20 0 -30 subgraph block ]
  trans [ translate 20 0 -20 subgraph block ]
  trans [ translate 20 0 -10 subgraph block ]
  trans [ translate 20 0 0 subgraph block ]
  trans [ translate 20 0 10 subgraph block ]
  trans [ translate 20 0 20 subgraph block ]
  trans [ translate 20 0 30 subgraph block ]
  trans [ translate 20 0 40 subgraph block ]
  trans [ translate 30 0 -50 subgraph block ]
  trans [ translate 30 0 -40 subgraph block ]
  trans [ translate 30 0 -30 subgraph block ]
  trans [ translate 30 0 -20 subgraph block ]
  trans [ translate 30 0 -10 subgraph block ]
  trans [ translate 30 0 0 subgraph block ]
  trans [ translate 30 0 10 subgraph block ]
  trans [ translate 30 0 20 subgraph block ]
  trans [ translate 30 0 30 subgraph block ]
  trans [ translate 30 0 40 subgraph block ]
  trans [ translate 40 0 -50 subgraph block ]
  trans [ translate 40 0 -40 subgraph block ]
  trans [ translate 40 0 -30 subgraph block ]
  trans [ translate 40 0 -20 subgraph block ]
  trans [ translate 40 0 -10 subgraph block ]
  trans [ translate 40 0 0 subgraph block ]
  trans [ translate 40 0 10 subgraph block ]
  trans [ translate 40 0 20 subgraph block ]
  trans [ translate 40 0 30 subgraph block ]
  trans [ translate 40 0 40 subgraph block ]
]
