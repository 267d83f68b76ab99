set terminal pngcairo size 900,700 noenhanced font 'sans,11'
set output '/work/runs/real10/figures/signature_plastic_adhesion.png'
set title 'plastic_adhesion: residual and signature x estimated strength -0.0109 (sigma units; z = -1.76)'
set xlabel 'observable'; set ylabel 'measured - simulated [sigma]'; set grid; set key top right
plot '/work/runs/real10/figures/signature_plastic_adhesion.dat' using 1:2 with impulses lw 4 lc rgb '#999' title 'residual', '' using 1:3 with linespoints pt 7 lc rgb '#a33' title 'signature x strength'
