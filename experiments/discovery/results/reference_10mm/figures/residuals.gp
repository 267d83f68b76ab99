set terminal pngcairo size 900,700 noenhanced font 'sans,11'
set output '/work/runs/real10/figures/residuals.png'
set title 'Standardised residuals (measured - simulated) / sd, per observable'
set ylabel 'z'; set grid ytics; set xtics rotate by -40 ('slump slump_flow_mm' 1, 'slump slump_mm' 2) font ',8'; set key top right
set style fill solid 0.6 border -1; set boxwidth 0.4; set xrange [0:3]
plot '/work/runs/real10/figures/residuals.dat' using ($1-0.2):2 with boxes lc rgb '#a33' title 'before', \
      2 with lines dt 2 lc rgb 'black' notitle, -2 with lines dt 2 lc rgb 'black' notitle
