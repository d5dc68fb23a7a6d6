set arrow @n@ from 0,0,0 to @to@ head filled size 0.07,20 @style@ lc rgb '@colour@'
set label @n@ @text@ at @at@ tc rgb '@colour@'
