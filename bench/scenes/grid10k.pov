// 10000 objects, the same scene as the .sc written by bench/gen_scene
#version 3.7;
global_settings { max_trace_level 5 assumed_gamma 1.0 ambient_light rgb 0.2 }
camera { perspective location <0,45,85> up y right -x*1.33333 angle 63.742 look_at <0,0,-5> }
background { rgb <0.5,0.65,0.85> }
light_source { <30,200,40> rgb 0.8 }
light_source { <0.3,1,0.5>*1e6 rgb 0.3 parallel point_at <0,0,0> }
#declare Block = union {
  box { -0.5, 0.5 matrix <0.5,0,0,0,0.5,0,0,0,0.5,0.5,0.25,0.5> pigment { rgb <0.3,0.3,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.485632,0.0543684,-0.229796,0.0553752,0.494625,0.234051,0.22554,-0.22554,0.423277,0.5,0.275,1.5> pigment { rgb <0.37,0.36,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.369935,0.210065,-0.394235,0.217309,0.382691,0.407829,0.38064,-0.38064,0.154357,0.5,0.3,2.5> pigment { rgb <0.44,0.42,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.59941,0.0205901,-0.157111,0.0215864,0.628414,0.164713,0.149509,-0.149509,0.550812,0.5,0.325,3.5> pigment { rgb <0.51,0.48,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  box { -0.5, 0.5 matrix <0.504873,0.155127,-0.395776,0.164528,0.535472,0.419762,0.37179,-0.37179,0.32855,0.5,0.35,4.5> pigment { rgb <0.58,0.54,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.698668,0.00133185,-0.0431399,0.00095132,0.499049,0.0308142,0.0400585,-0.0400585,0.647527,0.5,0.25,5.5> pigment { rgb <0.65,0.6,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.644964,0.0950364,-0.350129,0.0706352,0.479365,0.260231,0.32174,-0.32174,0.505338,0.5,0.275,6.5> pigment { rgb <0.72,0.66,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.297702,0.202298,-0.347058,0.242757,0.357243,0.416469,0.492822,-0.492822,0.135474,0.5,0.3,7.5> pigment { rgb <0.79,0.72,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.512674,0.0273256,-0.167387,0.0328919,0.617108,0.201484,0.229382,-0.229382,0.665108,0.5,0.325,8.5> pigment { rgb <0.86,0.78,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.421657,0.158343,-0.365421,0.191103,0.508897,0.441026,0.315018,-0.315018,0.226995,0.5,0.35,9.5> pigment { rgb <0.93,0.84,0.45> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.61529,0.0047096,-0.0761284,0.00379807,0.496202,0.0613939,0.0650775,-0.0650775,0.521948,1.5,0.25,0.5> pigment { rgb <0.3,0.9,0.4> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.555059,0.104941,-0.341316,0.0874505,0.46255,0.28443,0.289601,-0.289601,0.381919,1.5,0.275,1.5> pigment { rgb <0.37,0.3,0.35> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.386585,0.313415,-0.492263,0.268642,0.331359,0.42194,0.414908,-0.414908,0.0616718,1.5,0.3,2.5> pigment { rgb <0.44,0.36,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.687152,0.0528481,-0.269498,0.0464206,0.603579,0.236722,0.225796,-0.225796,0.531444,1.5,0.325,3.5> pigment { rgb <0.51,0.42,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.343652,0.156348,-0.327809,0.218888,0.481112,0.458933,0.426152,-0.426152,0.243494,1.5,0.35,4.5> pigment { rgb <0.58,0.48,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.5308,0.00920003,-0.0988269,0.00851855,0.491481,0.0915064,0.124449,-0.124449,0.65683,1.5,0.25,5.5> pigment { rgb <0.65,0.54,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.468542,0.111458,-0.32318,0.105693,0.444307,0.306464,0.395617,-0.395617,0.43712,1.5,0.275,6.5> pigment { rgb <0.72,0.6,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.31541,0.30459,-0.438339,0.294764,0.305236,0.424199,0.523179,-0.523179,0.0129148,1.5,0.3,7.5> pigment { rgb <0.79,0.66,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.596976,0.0630244,-0.274314,0.0620695,0.587931,0.270158,0.207813,-0.207813,0.404509,1.5,0.325,8.5> pigment { rgb <0.86,0.72,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.45233,0.24767,-0.473347,0.24767,0.45233,0.473347,0.358391,-0.358391,0.154957,1.5,0.35,9.5> pigment { rgb <0.93,0.78,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.717686,0.0223137,-0.178965,0.0150768,0.484923,0.120922,0.135433,-0.135433,0.526228,2.5,0.25,0.5> pigment { rgb <0.3,0.84,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.38616,0.11384,-0.296515,0.125224,0.424776,0.326166,0.349887,-0.349887,0.321337,2.5,0.275,1.5> pigment { rgb <0.37,0.9,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.539342,0.000657699,-0.0266357,0.000730777,0.599269,0.0295952,0.0305817,-0.0305817,0.61849,2.5,0.3,2.5> pigment { rgb <0.44,0.3,0.45> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.508866,0.0711342,-0.269064,0.0797194,0.570281,0.301537,0.301537,-0.301537,0.490561,2.5,0.325,3.5> pigment { rgb <0.51,0.36,0.4> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.374453,0.245547,-0.428826,0.277231,0.422769,0.484158,0.470325,-0.470325,0.14138,2.5,0.35,4.5> pigment { rgb <0.58,0.42,0.35> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.629082,0.0309184,-0.197232,0.0234231,0.476577,0.149418,0.212174,-0.212174,0.643479,2.5,0.25,5.5> pigment { rgb <0.65,0.48,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.514315,0.185685,-0.437037,0.145895,0.404105,0.343386,0.46201,-0.46201,0.347409,2.5,0.275,6.5> pigment { rgb <0.72,0.54,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.735445,0.00455531,-0.0818558,0.00369349,0.596307,0.0663695,0.0553079,-0.0553079,0.493844,2.5,0.3,7.5> pigment { rgb <0.79,0.6,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.423665,0.0763354,-0.254325,0.099236,0.550764,0.330623,0.269585,-0.269585,0.368169,2.5,0.325,8.5> pigment { rgb <0.86,0.66,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.302905,0.237095,-0.378992,0.307346,0.392654,0.491285,0.393028,-0.393028,0.0682468,2.5,0.35,9.5> pigment { rgb <0.93,0.72,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.541147,0.0388526,-0.205061,0.0334937,0.466506,0.176777,0.208596,-0.208596,0.510955,3.5,0.25,0.5> pigment { rgb <0.3,0.78,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.431127,0.188873,-0.403555,0.167549,0.382451,0.357992,0.403555,-0.403555,0.242253,3.5,0.275,1.5> pigment { rgb <0.37,0.84,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.650198,0.00980241,-0.112903,0.00891128,0.591089,0.102639,0.111192,-0.111192,0.630692,3.5,0.3,2.5> pigment { rgb <0.44,0.9,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.570262,0.129738,-0.384668,0.120471,0.529529,0.357191,0.373677,-0.373677,0.427938,3.5,0.325,3.5> pigment { rgb <0.51,0.3,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  sphere { 0, 0.5 matrix <0.382913,0.357087,-0.52294,0.337785,0.362215,0.494673,0.50174,-0.50174,0.0247786,3.5,0.35,4.5> pigment { rgb <0.58,0.36,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.454788,0.045212,-0.20279,0.045212,0.454788,0.20279,0.300129,-0.300129,0.606173,3.5,0.25,5.5> pigment { rgb <0.65,0.42,0.45> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.353435,0.186565,-0.363149,0.19002,0.35998,0.369874,0.336249,-0.336249,0.154508,3.5,0.275,6.5> pigment { rgb <0.72,0.48,0.4> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.5642,0.0157996,-0.133523,0.0163444,0.583656,0.138127,0.122012,-0.122012,0.501125,3.5,0.3,7.5> pigment { rgb <0.79,0.54,0.35> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.48335,0.13665,-0.363455,0.143262,0.506738,0.381042,0.328282,-0.328282,0.313148,3.5,0.325,8.5> pigment { rgb <0.86,0.6,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.659548,0.000452262,-0.0244247,0.000479671,0.69952,0.025905,0.0218342,-0.0218342,0.589191,3.5,0.35,9.5> pigment { rgb <0.93,0.66,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.618116,0.0818845,-0.318164,0.0584889,0.441511,0.22726,0.281802,-0.281802,0.474948,4.5,0.25,0.5> pigment { rgb <0.3,0.72,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.453232,0.286768,-0.509848,0.213139,0.336862,0.378941,0.447839,-0.447839,0.146218,4.5,0.275,1.5> pigment { rgb <0.37,0.78,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.478386,0.0216136,-0.143803,0.0259364,0.574064,0.172564,0.195572,-0.195572,0.621211,4.5,0.3,2.5> pigment { rgb <0.44,0.84,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.400899,0.139101,-0.333963,0.167437,0.482563,0.401992,0.439099,-0.439099,0.344215,4.5,0.325,3.5> pigment { rgb <0.51,0.9,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  box { -0.5, 0.5 matrix <0.577178,0.00282227,-0.0570779,0.00340618,0.696594,0.0688872,0.0728236,-0.0728236,0.732798,4.5,0.35,4.5> pigment { rgb <0.58,0.3,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.529203,0.0907969,-0.31,0.0732233,0.426777,0.25,0.25,-0.25,0.353553,4.5,0.25,5.5> pigment { rgb <0.65,0.36,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.375927,0.284073,-0.462149,0.236727,0.313273,0.385124,0.371119,-0.371119,0.0737617,4.5,0.275,6.5> pigment { rgb <0.72,0.42,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.656117,0.0438831,-0.239969,0.0376141,0.562386,0.205687,0.191975,-0.191975,0.489787,4.5,0.3,7.5> pigment { rgb <0.79,0.48,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.520493,0.219507,-0.478021,0.192811,0.457189,0.419883,0.381125,-0.381125,0.239975,4.5,0.325,8.5> pigment { rgb <0.86,0.54,0.45> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.493593,0.00640748,-0.0795322,0.00897048,0.69103,0.111345,0.0986199,-0.0986199,0.604109,4.5,0.35,9.5> pigment { rgb <0.93,0.6,0.4> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.443553,0.0964473,-0.292505,0.0893031,0.410697,0.270838,0.352089,-0.352089,0.417812,5.5,0.25,0.5> pigment { rgb <0.3,0.66,0.35> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.305177,0.274823,-0.40956,0.260608,0.289392,0.388376,0.480174,-0.480174,0.0355885,5.5,0.275,1.5> pigment { rgb <0.37,0.72,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.567002,0.0529983,-0.245154,0.0512887,0.548711,0.237245,0.28074,-0.28074,0.588617,5.5,0.3,2.5> pigment { rgb <0.44,0.78,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.437437,0.222563,-0.441265,0.21919,0.43081,0.434579,0.494751,-0.494751,0.24092,5.5,0.325,3.5> pigment { rgb <0.51,0.84,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.68287,0.0171302,-0.152956,0.0171302,0.68287,0.152956,0.109254,-0.109254,0.475528,5.5,0.35,4.5> pigment { rgb <0.58,0.9,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.582223,0.157777,-0.428629,0.106606,0.393394,0.289614,0.306991,-0.306991,0.303995,5.5,0.25,5.5> pigment { rgb <0.65,0.3,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.499848,0.00015229,-0.0123388,0.000167519,0.549832,0.0135727,0.0138195,-0.0138195,0.559659,5.5,0.275,6.5> pigment { rgb <0.72,0.36,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.479829,0.0601706,-0.240298,0.0668562,0.533144,0.266998,0.262548,-0.262548,0.458516,5.5,0.3,7.5> pigment { rgb <0.79,0.42,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.360157,0.219843,-0.39794,0.246375,0.403625,0.445967,0.425384,-0.425384,0.149992,5.5,0.325,8.5> pigment { rgb <0.86,0.48,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.595357,0.0246435,-0.171299,0.0278233,0.672177,0.193402,0.179588,-0.179588,0.598328,5.5,0.35,9.5> pigment { rgb <0.93,0.54,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.495,0.165,-0.404166,0.125,0.375,0.306186,0.416413,-0.416413,0.34,6.5,0.25,0.5> pigment { rgb <0.3,0.6,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.697391,0.00260885,-0.0603223,0.00204981,0.54795,0.0473961,0.061184,-0.061184,0.704708,6.5,0.275,1.5> pigment { rgb <0.37,0.66,0.45> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.636156,0.103844,-0.363486,0.0841981,0.515802,0.294719,0.363486,-0.363486,0.532311,6.5,0.3,2.5> pigment { rgb <0.44,0.72,0.4> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.289109,0.210891,-0.349201,0.274159,0.375841,0.453961,0.349201,-0.349201,0.0782172,6.5,0.325,3.5> pigment { rgb <0.51,0.78,0.35> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.508396,0.0316042,-0.179262,0.0409684,0.659032,0.232377,0.175942,-0.175942,0.467962,6.5,0.35,4.5> pigment { rgb <0.58,0.84,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.412559,0.167441,-0.371697,0.144345,0.355655,0.320428,0.35888,-0.35888,0.236666,6.5,0.25,5.5> pigment { rgb <0.65,0.9,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.613226,0.00677424,-0.0911498,0.0060094,0.543991,0.0808587,0.0867393,-0.0867393,0.577107,6.5,0.275,6.5> pigment { rgb <0.72,0.3,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.546499,0.113501,-0.352216,0.103182,0.496818,0.320196,0.330869,-0.330869,0.406757,6.5,0.3,7.5> pigment { rgb <0.79,0.36,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.374415,0.325585,-0.493769,0.302329,0.347671,0.4585,0.4585,-0.4585,0.0453417,6.5,0.325,8.5> pigment { rgb <0.86,0.42,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.680308,0.0596919,-0.284987,0.0564653,0.643535,0.269583,0.26188,-0.26188,0.570296,6.5,0.35,9.5> pigment { rgb <0.93,0.48,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.335505,0.164495,-0.332232,0.164495,0.335505,0.332232,0.471769,-0.471769,0.242834,7.5,0.25,0.5> pigment { rgb <0.3,0.54,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.528202,0.0117977,-0.111639,0.0120162,0.537984,0.113706,0.152986,-0.152986,0.707666,7.5,0.275,1.5> pigment { rgb <0.37,0.6,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.460458,0.119542,-0.331796,0.123664,0.476336,0.343237,0.286031,-0.286031,0.293893,7.5,0.3,2.5> pigment { rgb <0.44,0.66,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.619953,4.72099e-05,-0.00765124,4.94942e-05,0.649951,0.00802146,0.00654058,-0.00654058,0.529919,7.5,0.325,3.5> pigment { rgb <0.51,0.72,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  sphere { 0, 0.5 matrix <0.590044,0.0699564,-0.287323,0.0741962,0.625804,0.304737,0.24379,-0.24379,0.441286,7.5,0.35,4.5> pigment { rgb <0.58,0.78,0.45> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.440587,0.259413,-0.478109,0.185295,0.314705,0.341506,0.402977,-0.402977,0.152703,7.5,0.25,5.5> pigment { rgb <0.65,0.84,0.4> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.713058,0.026942,-0.196016,0.0200244,0.529976,0.145688,0.16423,-0.16423,0.574854,7.5,0.275,6.5> pigment { rgb <0.72,0.9,0.35> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.37876,0.12124,-0.303054,0.145489,0.454511,0.363665,0.393971,-0.393971,0.334775,7.5,0.3,7.5> pigment { rgb <0.79,0.3,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.538521,0.00147908,-0.0399129,0.00178038,0.64822,0.0480433,0.0502607,-0.0502607,0.676275,7.5,0.325,8.5> pigment { rgb <0.86,0.36,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.502093,0.0779074,-0.279703,0.0940262,0.605974,0.337572,0.342394,-0.342394,0.519261,7.5,0.35,9.5> pigment { rgb <0.93,0.42,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.363831,0.256169,-0.431746,0.206588,0.293412,0.348182,0.51531,-0.51531,0.1285,8.5,0.25,0.5> pigment { rgb <0.3,0.48,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.624032,0.0359678,-0.211873,0.0299732,0.520027,0.176561,0.16051,-0.16051,0.445503,8.5,0.275,1.5> pigment { rgb <0.37,0.54,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.50343,0.19657,-0.44488,0.168489,0.431511,0.381326,0.336838,-0.336838,0.232337,8.5,0.3,2.5> pigment { rgb <0.44,0.6,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.733202,0.00679795,-0.0998425,0.00597117,0.644029,0.0876995,0.0755565,-0.0755565,0.549711,8.5,0.325,3.5> pigment { rgb <0.51,0.66,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  box { -0.5, 0.5 matrix <0.417283,0.0827174,-0.262741,0.115804,0.584196,0.367838,0.310035,-0.310035,0.394787,8.5,0.35,4.5> pigment { rgb <0.58,0.72,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.293532,0.246468,-0.380385,0.228211,0.271789,0.352208,0.436738,-0.436738,0.0540366,8.5,0.25,5.5> pigment { rgb <0.65,0.78,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.535934,0.0440661,-0.217332,0.0417868,0.508213,0.20609,0.243561,-0.243561,0.551231,8.5,0.275,6.5> pigment { rgb <0.72,0.84,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.421094,0.198906,-0.409287,0.19249,0.40751,0.396085,0.448896,-0.448896,0.24369,8.5,0.3,7.5> pigment { rgb <0.79,0.9,0.45> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.647216,0.0127836,-0.128637,0.01259,0.63741,0.126688,0.138383,-0.138383,0.682496,8.5,0.325,8.5> pigment { rgb <0.86,0.3,0.4> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.560635,0.139365,-0.395304,0.139365,0.560635,0.395304,0.417893,-0.417893,0.445343,8.5,0.35,9.5> pigment { rgb <0.93,0.36,0.35> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.74,0,0,0,0.5,0,0,0,0.5,9.5,0.25,0.5> pigment { rgb <0.3,0.42,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.449659,0.0503411,-0.212774,0.0553752,0.494625,0.234051,0.22554,-0.22554,0.423277,9.5,0.275,1.5> pigment { rgb <0.37,0.48,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.344422,0.195578,-0.367046,0.217309,0.382691,0.407829,0.38064,-0.38064,0.154357,9.5,0.3,2.5> pigment { rgb <0.44,0.54,0.85> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.560738,0.0192617,-0.146975,0.0215864,0.628414,0.164713,0.149509,-0.149509,0.550812,9.5,0.325,3.5> pigment { rgb <0.51,0.6,0.8> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 reflection 0.5 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.474275,0.145725,-0.37179,0.164528,0.535472,0.419762,0.37179,-0.37179,0.32855,9.5,0.35,4.5> pigment { rgb <0.58,0.66,0.75> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.658744,0.00125574,-0.0406748,0.00095132,0.499049,0.0308142,0.0400585,-0.0400585,0.647527,9.5,0.25,5.5> pigment { rgb <0.65,0.72,0.7> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  sphere { 0, 0.5 matrix <0.610101,0.0898993,-0.331203,0.0706352,0.479365,0.260231,0.32174,-0.32174,0.505338,9.5,0.275,6.5> pigment { rgb <0.72,0.78,0.65> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  box { -0.5, 0.5 matrix <0.440599,0.299401,-0.513645,0.242757,0.357243,0.416469,0.492822,-0.492822,0.135474,9.5,0.3,7.5> pigment { rgb <0.79,0.84,0.6> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <0.474699,0.0253015,-0.154988,0.0328919,0.617108,0.201484,0.229382,-0.229382,0.665108,9.5,0.325,8.5> pigment { rgb <0.86,0.9,0.55> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <0.392577,0.147423,-0.34022,0.191103,0.508897,0.441026,0.315018,-0.315018,0.226995,9.5,0.35,9.5> pigment { rgb <0.93,0.3,0.5> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
}
object { Block translate <-50,0,-50> }
object { Block translate <-50,0,-40> }
object { Block translate <-50,0,-30> }
object { Block translate <-50,0,-20> }
object { Block translate <-50,0,-10> }
object { Block translate <-50,0,0> }
object { Block translate <-50,0,10> }
object { Block translate <-50,0,20> }
object { Block translate <-50,0,30> }
object { Block translate <-50,0,40> }
object { Block translate <-40,0,-50> }
object { Block translate <-40,0,-40> }
object { Block translate <-40,0,-30> }
object { Block translate <-40,0,-20> }
object { Block translate <-40,0,-10> }
object { Block translate <-40,0,0> }
object { Block translate <-40,0,10> }
object { Block translate <-40,0,20> }
object { Block translate <-40,0,30> }
object { Block translate <-40,0,40> }
object { Block translate <-30,0,-50> }
object { Block translate <-30,0,-40> }
object { Block translate <-30,0,-30> }
object { Block translate <-30,0,-20> }
object { Block translate <-30,0,-10> }
object { Block translate <-30,0,0> }
object { Block translate <-30,0,10> }
object { Block translate <-30,0,20> }
object { Block translate <-30,0,30> }
object { Block translate <-30,0,40> }
object { Block translate <-20,0,-50> }
object { Block translate <-20,0,-40> }
object { Block translate <-20,0,-30> }
object { Block translate <-20,0,-20> }
object { Block translate <-20,0,-10> }
object { Block translate <-20,0,0> }
object { Block translate <-20,0,10> }
object { Block translate <-20,0,20> }
object { Block translate <-20,0,30> }
object { Block translate <-20,0,40> }
object { Block translate <-10,0,-50> }
object { Block translate <-10,0,-40> }
object { Block translate <-10,0,-30> }
object { Block translate <-10,0,-20> }
object { Block translate <-10,0,-10> }
object { Block translate <-10,0,0> }
object { Block translate <-10,0,10> }
object { Block translate <-10,0,20> }
object { Block translate <-10,0,30> }
object { Block translate <-10,0,40> }
object { Block translate <0,0,-50> }
object { Block translate <0,0,-40> }
object { Block translate <0,0,-30> }
object { Block translate <0,0,-20> }
object { Block translate <0,0,-10> }
object { Block translate <0,0,0> }
object { Block translate <0,0,10> }
object { Block translate <0,0,20> }
object { Block translate <0,0,30> }
object { Block translate <0,0,40> }
object { Block translate <10,0,-50> }
object { Block translate <10,0,-40> }
object { Block translate <10,0,-30> }
object { Block translate <10,0,-20> }
object { Block translate <10,0,-10> }
object { Block translate <10,0,0> }
object { Block translate <10,0,10> }
object { Block translate <10,0,20> }
object { Block translate <10,0,30> }
object { Block translate <10,0,40> }
object { Block translate <20,0,-50> }
object { Block translate <20,0,-40> }
object { Block translate <20,0,-30> }
object { Block translate <20,0,-20> }
object { Block translate <20,0,-10> }
object { Block translate <20,0,0> }
object { Block translate <20,0,10> }
object { Block translate <20,0,20> }
object { Block translate <20,0,30> }
object { Block translate <20,0,40> }
object { Block translate <30,0,-50> }
object { Block translate <30,0,-40> }
object { Block translate <30,0,-30> }
object { Block translate <30,0,-20> }
object { Block translate <30,0,-10> }
object { Block translate <30,0,0> }
object { Block translate <30,0,10> }
object { Block translate <30,0,20> }
object { Block translate <30,0,30> }
object { Block translate <30,0,40> }
object { Block translate <40,0,-50> }
object { Block translate <40,0,-40> }
object { Block translate <40,0,-30> }
object { Block translate <40,0,-20> }
object { Block translate <40,0,-10> }
object { Block translate <40,0,0> }
object { Block translate <40,0,10> }
object { Block translate <40,0,20> }
object { Block translate <40,0,30> }
object { Block translate <40,0,40> }
