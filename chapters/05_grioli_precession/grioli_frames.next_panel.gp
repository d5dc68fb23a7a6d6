# Before the second panel: the key is the first panel's alone.
unset key
