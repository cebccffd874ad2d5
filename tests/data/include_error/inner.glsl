float inner() {
  float x = 1.0;
  // the next line is the error
  return x + no_such_name;
}
