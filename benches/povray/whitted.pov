// POV-Ray 3.7 twin of scenes/whitted.json, written by hand for
// benches/povray/compare.sh. Same geometry, camera, lights and Phong,
// reflection and refraction settings; where POV-Ray's model differs from
// raytree's, the numbers are converted (see the notes) so the images match.

#version 3.7;

global_settings {
  assumed_gamma 1.0                // colors are linear, as in raytree
  ambient_light rgb <1, 1, 1>      // "ambient_light": [1, 1, 1]
  max_trace_level 8                // "max_depth": 8
  adc_bailout 1/1024               // raytree's default cutoff
}

background { color rgb <0.18, 0.36, 0.75> }

// raytree's lecture camera puts the first and last pixel centers at -W and +W,
// W = tan(fov/2) at distance 1; POV-Ray spans the right vector edge to edge, so
// its right and up vectors are one pixel spacing per pixel.
#declare Eye = <0, 1.6, 7>;
#declare LookAt = <0, 1, 0>;
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

light_source { <-4, 7, 6> color rgb <0.75, 0.75, 0.75> }   // key
light_source { <5, 5, 4> color rgb <0.5, 0.5, 0.5> }       // fill

// The checkerboard: raytree flattens the pattern onto the plane; POV-Ray's 3D
// checker is moved half a cell down so the plane y = 0 is mid-cell.
plane {
  y, 0
  texture {
    pigment { checker color rgb <0.9, 0.08, 0.05> color rgb <0.95, 0.8, 0.08> translate -0.5 * y }
    finish { ambient 0.15 diffuse 0.75 phong 0.2 phong_size 20 }
  }
}

sphere {
  <-1.3, 1.3, -1.8>, 1.3
  texture {
    pigment { color rgb <0.7, 0.7, 0.7> }
    finish { ambient 0.02 diffuse 0.08 phong 0.8 phong_size 200 reflection 0.85 }
  }
}

// Glass: transmit is raytree's k_rfa. POV-Ray scales a transparent surface's
// ambient and diffuse by (1 - transmit); the diffuse is divided by that here
// (0.02 / 0.12) so the product is raytree's k_d.
#declare Glass = texture {
  pigment { color rgbt <1, 1, 1, 0.88> }
  finish { ambient 0 diffuse 0.02 / 0.12 phong 0.9 phong_size 300 reflection 0.1 }
}
sphere { <0.9, 1.0, 1.2>, 0.9 texture { Glass } interior { ior 1.5 } }

// The air cavity: fully transparent, index 1.
sphere {
  <0.9, 1.0, 1.2>, 0.25
  texture { pigment { color rgbt <1, 1, 1, 1> } finish { ambient 0 diffuse 0 phong 0 reflection 0 } }
  interior { ior 1.0 }
}
