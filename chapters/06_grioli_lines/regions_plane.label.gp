set label @text@ at @x@,@y@ center font ',15' front
