// The CRT scene language (see docs/language.md). Newlines carry no meaning: statements end where
// the parser can no longer extend an expression, which is why a line starting with + - ^ ( [ <
// continues the expression before it.
grammar CRT;

script : statement* EOF ;

statement
    : SETTINGS '{' attribute* '}'                         # settingsBlock
    | SCENE '{' statement* '}'                            # sceneBlock
    | WHILE '(' expression ')' block                      # whileLoop
    | ifChain                                             # ifStatement
    | expression                                          # expressionStatement
    ;

ifChain : IF '(' expression ')' block (ELSE (ifChain | block))? ;

block : '{' statement* '}' ;

attribute : key=(IDENT | SCALE | ROTATE | TRANSLATE) '->' expression ;   // an attribute may be named like a modifier (a texture's scale)

// Level 12 of the precedence table; only a plain identifier may be assigned.
expression
    : <assoc=right> IDENT '=' expression                  # assignment
    | operation                                           # plainExpression
    ;

// Levels 8 to 11. Their operands are arithmetic, so that '<' and '>' after a modifier argument
// close the modifier list instead of starting a comparison.
operation
    : arithmetic                                                      # arithmeticOperation
    | operation op=('<=' | '>=' | '<' | '>' | '==' | '!=') operation  # comparison
    | operation '&&' operation                                        # and
    | operation '||' operation                                        # or
    | <assoc=right> operation '?' operation ':' operation             # conditional
    ;

// Levels 1 to 7.
arithmetic
    : arithmetic '[' expression ']'                                   # index
    | arithmetic '(' (expression (',' expression)*)? ')'              # call
    | arithmetic '<' modifier (',' modifier)* '>'                     # modified
    | <assoc=right> op=('+' | '-') arithmetic                         # sign
    | '!' arithmetic                                                  # not
    | arithmetic op=('*' | '/' | '%') arithmetic                      # multiplicative
    | arithmetic op=('+' | '-' | '^') arithmetic                      # additive
    | primary                                                         # atom
    ;

modifier : kind=(TRANSLATE | ROTATE | SCALE) arithmetic ;

// The locals cache the decoded literal so loops do not parse the same text again.
primary locals [Object cached]
    : INT                                                             # intLiteral
    | FLOAT                                                           # floatLiteral
    | (STRING | UNTERMINATED_STRING)                                  # stringLiteral
    | (TRUE | FALSE)                                                  # booleanLiteral
    | IDENT                                                           # variable
    | NAME '{' attribute* '}'                                         # object
    | MACRO '(' (IDENT (',' IDENT)*)? ')' '{' statement* '}'          # macro
    | '[' (expression (',' expression)*)? ']'                         # list
    | '(' expression ')'                                              # parenthesized
    ;

SETTINGS  : 'Settings' ;
SCENE     : 'Scene' ;
MACRO     : 'Macro' ;
SCALE     : 'scale' ;
TRANSLATE : 'translate' ;
ROTATE    : 'rotate' ;
TRUE      : 'true' ;
FALSE     : 'false' ;
WHILE     : 'while' ;
IF        : 'if' ;
ELSE      : 'else' ;

ARROW  : '->' ;
LE     : '<=' ;
GE     : '>=' ;
EQ     : '==' ;
NE     : '!=' ;
AND    : '&&' ;
OR     : '||' ;
LT     : '<' ;
GT     : '>' ;
ASSIGN : '=' ;
PLUS   : '+' ;
MINUS  : '-' ;
STAR   : '*' ;
SLASH  : '/' ;
PERCENT: '%' ;
CARET  : '^' ;
BANG   : '!' ;
QUESTION : '?' ;
COLON  : ':' ;
COMMA  : ',' ;
LPAREN : '(' ;
RPAREN : ')' ;
LBRACE : '{' ;
RBRACE : '}' ;
LBRACKET : '[' ;
RBRACKET : ']' ;

FLOAT
    : DIGIT+ '.' DIGIT* EXPONENT?
    | '.' DIGIT+ EXPONENT?
    | DIGIT+ EXPONENT
    ;
INT : DIGIT+ ;

// A number whose exponent has no digits ("1e", "2.5e-"). Lexed as one FLOAT so that the parser
// goes on without a cascade; the compiler reports it.
MALFORMED_FLOAT : (DIGIT+ ('.' DIGIT*)? | '.' DIGIT+) [eE] [+-]? -> type(FLOAT) ;

// Escapes other than \" and \\ are lexed here and rejected by the compiler with a clear message.
STRING : '"' ('\\' ~[\r\n] | ~["\\\r\n])* '"' ;

IDENT : [a-z] [a-zA-Z0-9_]* ;
NAME  : [A-Z] [a-zA-Z0-9_]* ;

COMMENT : '--' ~[\r\n]* -> skip ;
WS      : [ \t\r\n\f\uFEFF]+ -> skip ;

// Mistakes the lexer can recognise are reported once each by the compiler. An unterminated string
// still stands where a string may, and a stray character is kept off the parser's channel, so
// that neither also produces a cascade of parse errors.
UNTERMINATED_STRING : '"' ('\\' ~[\r\n] | ~["\\\r\n])* '\\'? ;
BAD_CHARACTER       : . -> channel(HIDDEN) ;

fragment DIGIT    : [0-9] ;
fragment EXPONENT : [eE] [+-]? DIGIT+ ;
