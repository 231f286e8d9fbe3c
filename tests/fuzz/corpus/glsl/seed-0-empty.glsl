0 an empty shader
