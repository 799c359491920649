Points { (0,0,0.2) ; }
