float outside() { return 0.0; }
