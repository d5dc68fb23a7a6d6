set arrow @n@ from @from@ to @to@ head filled size screen 0.025,20,60 lw 2.5 lc rgb '#000000'
