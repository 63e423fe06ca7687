grammar MASL;
program : EOF ;
WS : [ \t\r\n]+ -> skip ;
