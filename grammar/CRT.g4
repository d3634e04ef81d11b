grammar CRT;
script : EOF ;
WS : [ \t\r\n]+ -> skip ;
