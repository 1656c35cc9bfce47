// POV-Ray 3.7 twin of scenes/spheres.json, written by hand for
// benches/povray/compare.sh: camera, lights, floor and the seven materials are
// here; the 2,000 sphere placements are in spheres.inc, listed from
// scenes/spheres.json (tests/povray.rs checks that the two agree).

#version 3.7;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb <1, 1, 1>
  max_trace_level 8
  adc_bailout 1/1024
}

background { color rgb <0.18, 0.36, 0.75> }

// The lecture camera's pixel spacing (see whitted.pov).
#declare Eye = <0, 20, 26>;
#declare LookAt = <0, 1.25, 0>;
#declare N = vnormalize(Eye - LookAt);
#declare U = vnormalize(vcross(y, N));
#declare V = vcross(N, U);
#declare Spacing = 2 * tan(radians(50) / 2) / (image_width - 1);
camera {
  perspective
  location Eye
  direction -N
  right U * Spacing * image_width
  up V * Spacing * image_height
}

light_source { <-12, 20, 16> color rgb <0.7, 0.7, 0.7> }
light_source { <14, 12, 8> color rgb <0.45, 0.45, 0.45> }

plane { y, 0 texture { pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient 0.1 diffuse 0.8 phong 0 } } }

#macro Diffuse(C)
  texture { pigment { color rgb C } finish { ambient 0.1 diffuse 0.8 phong 0.3 phong_size 30 } }
#end
#declare T_red = Diffuse(<0.8, 0.12, 0.1>)
#declare T_green = Diffuse(<0.15, 0.65, 0.2>)
#declare T_blue = Diffuse(<0.15, 0.3, 0.85>)
#declare T_ivory = Diffuse(<0.9, 0.85, 0.7>)
#declare T_mirror = texture {
  pigment { color rgb <0.7, 0.7, 0.7> }
  finish { ambient 0.02 diffuse 0.08 phong 0.8 phong_size 200 reflection 0.8 }
}
// POV-Ray scales a transparent surface's diffuse by (1 - transmit): divided here
// so the product is raytree's k_d = 0.02.
#declare T_glass = texture {
  pigment { color rgbt <1, 1, 1, 0.85> }
  finish { ambient 0 diffuse 0.02 / 0.15 phong 0.9 phong_size 300 reflection 0.1 }
}
#declare I_glass = interior { ior 1.5 }

#include "spheres.inc"
