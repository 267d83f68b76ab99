# The 4 mm vane's start-up (centre set, seed 1, 150 mm fill): the vane relation's stress from the
# torque against the stresses measured on the sheared surface from the contact forces.
# Run in this directory: gnuplot startup_stress.gp  (writes startup_stress.png)
set terminal pngcairo size 900,600 font ',10' noenhanced
set output 'startup_stress.png'
set title 'Vane start-up at 5 rpm (4 mm spheres, centre set, seed 1, 150 mm fill)'
set xlabel 'angle turned [deg]'; set ylabel 'stress [Pa]'; set grid; set key bottom right; set yrange [0:800]
factor = 3.0106929e-4   # (pi D^3/2)(H/D + 1/3) of the 50 x 60 mm vane [m^3]
plot 'startup.dat' using 1:($3/factor) with lines lw 2 lc rgb '#8b5a2b' title 'vane relation: smoothed torque / factor', \
     'startup_stress.dat' using 1:3 with linespoints pt 7 ps 0.5 lc rgb '#1b9e77' title 'side: resisting shear (contact forces)', \
     'startup_stress.dat' using 1:2 with linespoints pt 7 ps 0.5 lc rgb '#d95f02' title 'side: normal stress sigma_rr', \
     'startup_stress.dat' using 1:6 with lines lc rgb '#7570b3' title 'sigma_n on the sheared surface (torque-weighted)'
