// POV-Ray 3.7 counterpart of bench/scenes/spheres.crt: n random spheres of radius 16/sqrt(n) in
// a 20 x 20 x 20 cube (POV-Ray's own random numbers: the same distribution, other positions).
//   povray -D -A +WT2 +W640 +H360 +FN File_Gamma=1.0 Declare=N=100000 +Ispheres.pov +Ospheres.png
#version 3.7;
#ifndef (N) #declare N = 1000; #end
global_settings { assumed_gamma 1.0 max_trace_level 1 adc_bailout 0 ambient_light rgb 0.16 }
camera {
  perspective location <0, 0, -32> look_at <0, 0, 0>
  right x * 640 / 360 up y
  angle 2 * degrees(atan(tan(radians(40 / 2)) * 640 / 360))
}
light_source { <-30, 40, -50> color rgb 0.8 }
background { rgb <0.05, 0.05, 0.08> }
#declare R = 16 / sqrt(N);
#declare S = seed(1);
#declare Paint = array[4] {
  texture { pigment { rgb <0.85, 0.3, 0.25> } finish { ambient 1 diffuse 1 phong 0.4 phong_size 30 } },
  texture { pigment { rgb <0.3, 0.6, 0.85> } finish { ambient 1 diffuse 1 phong 0.4 phong_size 30 } },
  texture { pigment { rgb <0.9, 0.8, 0.4> } finish { ambient 1 diffuse 1 phong 0.4 phong_size 30 } },
  texture { pigment { rgb <0.4, 0.8, 0.45> } finish { ambient 1 diffuse 1 phong 0.4 phong_size 30 } }
}
#declare I = 0;
#while (I < N)
  sphere { <rand(S) * 20 - 10, rand(S) * 20 - 10, rand(S) * 20 - 10>, R texture { Paint[mod(I, 4)] } }
  #declare I = I + 1;
#end
