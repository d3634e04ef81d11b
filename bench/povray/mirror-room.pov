// POV-Ray 3.7 twin of scenes/mirror-room.crt (a cross-check of CRT's reflection depth 8, glass and
// CSG; not a benchmark). CRT's recursiondepth 8 is max_trace_level 9; the shading maps as in
// docs/benchmarks.md. Compare with CRT's render:
//   povray -D -A +W960 +H540 +FN File_Gamma=1.0 +Imirror-room.pov +Omirror-room-povray.png
//   java ../tools/ImageCompare.java mirror-room-povray.png ../../docs/images/mirror-room.png
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 9 adc_bailout 0 ambient_light rgb <0.1125,0.108,0.0975> }
camera { perspective location <-2.6,2.6,-6.5> right x*960/540 up y angle 2*degrees(atan(tan(radians(55/2))*960/540)) look_at <0.6,1.3,2> }
light_source { <0,4.4,-1.5> color rgb <0.75,0.72,0.65> }
light_source { <-3.5,3.5,4> color rgb <0.3,0.32,0.4> }
#macro M(C,Kd,Ks,N,Kr) texture { pigment { rgb C } finish { ambient 1 diffuse Kd phong Ks phong_size N reflection {Kr} } } #end
#declare Mirror = M(<0.9,0.95,1>,0.05,0.3,200,0.85);
#declare Plaster = M(<0.85,0.8,0.7>,0.9,0,30,0);
plane { y, 0 M(<0.45,0.3,0.2>,0.8,0.3,40,0.15) }
plane { -y, -5 M(<0.95,0.95,0.95>,0.8,0,30,0) }
plane { x, -4.5 texture{Plaster} }
plane { -x, -4.5 texture{Mirror} }
plane { -z, -5 texture{Mirror} }
plane { z, -8 texture{Mirror} }
#macro Ped(X,Z,H) box { <X-0.45,0,Z-0.45>,<X+0.45,H,Z+0.45> texture{Plaster} } box { <X-0.6,H,Z-0.6>,<X+0.6,H+0.12,Z+0.6> texture{Plaster} } #end
Ped(0,1.5,0.9)
sphere { <0,1.62,1.5>,0.6 M(<0.8,0.8,0.85>,0.2,0.9,150,0.7) }
Ped(2.6,3,0.6)
intersection { box{-0.5,0.5} sphere{0,0.68} M(<0.9,0.7,0.3>,0.6,0.8,90,0.35) rotate <0,30,0> translate <2.6,1.22,3> }
sphere { <-1.8,0.7,2.8>,0.7 M(<0.8,0.12,0.1>,0.9,0.5,60,0) }
sphere { <1.6,0.45,-0.6>,0.45 texture { pigment { rgbf <1,1,1,0.85> } finish { ambient 1 diffuse 0.05 phong 0.9 phong_size 200 reflection {0.1} } } interior { ior 1.5 } }
box { <-5.08,0,1.83>,<-4.28,1.6,2.63> M(<0.1,0.55,0.55>,0.9,0.4,40,0) rotate <0,25,0> }
