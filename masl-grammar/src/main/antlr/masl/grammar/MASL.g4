/*
 * MASL, the Multi-Agent System Language: the whole syntax of MASL.md §2–3.
 *
 * Where the EBNF of §3 and good diagnostics pull apart, this grammar is the more permissive one and
 * the analysis reports the error with a precise message:
 *  - program headers (import, type, agents, Entry) may come in any order; the analysis checks the order;
 *  - declarations may stand anywhere in a block; the analysis reports one that follows an instruction;
 *  - label statements (`l.a.m(x)`, `l.x = .m()`, …) are expression statements: whether `l` names a
 *    label is a matter of name resolution, not of syntax.
 * Java keywords that MASL does not reserve (`class`, `super`, `public`, …) are ordinary identifiers.
 */
grammar MASL;

// Rule nodes are numbered once parsed, for the analysis's tables (MaslRuleContext).
options { contextSuperClass = MaslRuleContext; }

// ---------------------------------------------------------------- program structure (§3)

program
    : header* entryBlock? EOF
    ;

header
    : importDecl
    | typeDecl
    | agentsDecl
    | entryDecl
    ;

importDecl
    : IMPORT filePath (AS typeName=identifier)? SEMI
    ;

typeDecl
    : TYPE typeName=identifier USE filePath SEMI
    ;

// `Default.xml`, `../robots/Khepera.xml` or `"my robots/Khepera.xml"`. An unquoted path is the source text
// from its first to its last token; the analysis rejects one with white space or a comment inside.
filePath
    : StringLiteral
    | pathElement+
    ;

pathElement
    : ~(SEMI | AS | StringLiteral)
    ;

agentsDecl
    : typeName=identifier identifierList ASSIGN NEWAGENT LPAREN instanceType=identifier? RPAREN SEMI
    ;

entryDecl
    : ENTRY_DECL identifierList SEMI
    ;

identifierList
    : identifier (COMMA identifier)*
    ;

entryBlock
    : blockMode ENTRY name=identifier LPAREN test=expression RPAREN LBRACE blockItem* RBRACE
    ;

blockMode
    : SCALAR
    | SYNCHRONOUS
    | ASYNCHRONOUS
    ;

blockItem
    : declaration
    | reaction
    | statement
    ;

declaration
    : scope=(LOCAL | SHARED) FINAL? javaType identifierList limitedTo? (ASSIGN variableInitializer)? SEMI   # variableDecl
    | scope=(LOCAL | SHARED) EVENT identifierList SEMI                                                     # eventDecl
    | kind=(LLABEL | SLABEL) identifierList SEMI                                                           # labelDecl
    ;

limitedTo
    : LIMITED LPAREN typeName=identifier RPAREN
    ;

variableInitializer
    : arrayInitializer
    | expression
    ;

arrayInitializer
    : LBRACE (variableInitializer (COMMA variableInitializer)* COMMA?)? RBRACE
    ;

reaction
    : REACT LPAREN (event=identifier | DEFAULT) RPAREN LBRACE statement* RBRACE
    ;

// ---------------------------------------------------------------- statements (§3, §6, §8, §11, §12)

statement
    : entryBlock                                                                        # entryStmt
    | block                                                                             # blockStmt
    | SEMI                                                                              # emptyStmt
    | IF LPAREN expression RPAREN thenStmt=statement (ELSE elseStmt=statement)?         # ifStmt
    | WHILE LPAREN expression RPAREN statement                                          # whileStmt
    | FOR LPAREN init=expressionList? SEMI condition=expression? SEMI update=expressionList? RPAREN statement # forStmt
    | DO block LOOP SEMI?                                                               # doLoopStmt
    | EXIT (LPAREN levels=IntegerLiteral RPAREN)? SEMI                                  # exitStmt
    | BREAK (LPAREN jumpTarget RPAREN)? SEMI                                            # breakStmt
    | REELECT (LPAREN jumpTarget RPAREN)? SEMI                                          # reelectStmt
    | RESTART SEMI                                                                      # restartStmt
    | RESUME SEMI                                                                       # resumeStmt
    | CLEAREVENTS (LPAREN RPAREN)? SEMI                                                 # clearEventsStmt
    | EMIT (LPAREN event=identifier RPAREN | event=identifier) SEMI                     # emitStmt
    | EMITWITHMESSAGE LPAREN event=identifier COMMA message=expression RPAREN SEMI      # emitWithMessageStmt
    | SETACCEPTSTATE LPAREN expression RPAREN SEMI                                      # setAcceptStateStmt
    | WAIT LPAREN state=expression (COMMA timeout=expression)? RPAREN SEMI              # waitStmt
    | expression SEMI                                                                   # expressionStmt
    ;

block
    : LBRACE statement* RBRACE
    ;

jumpTarget
    : IntegerLiteral
    | identifier
    ;

expressionList
    : expression (COMMA expression)*
    ;

// ---------------------------------------------------------------- expressions (Java's, extended)

expression
    : primary                                                                  # primaryExpr
    | expression DOT identifier                                                # fieldAccess
    | expression DOT identifier arguments                                      # methodCall
    | expression DOT THIS                                                      # labelSelf
    | expression LBRACK index=expression RBRACK                                # arrayAccess
    | expression op=(INC | DEC)                                                # postfixExpr
    | op=(ADD | SUB | INC | DEC) expression                                    # prefixExpr
    | op=(TILDE | BANG) expression                                             # notExpr
    | LPAREN javaType RPAREN expression                                        # castExpr
    | left=expression op=(MUL | DIV | MOD) right=expression                    # binaryExpr
    | left=expression op=(ADD | SUB) right=expression                          # binaryExpr
    | left=expression shiftOperator right=expression                           # shiftExpr
    | left=expression op=(LT | GT | LE | GE) right=expression                  # binaryExpr
    | expression INSTANCEOF javaType                                           # instanceofExpr
    | left=expression op=(EQUAL | NOTEQUAL | DIAMOND) right=expression         # binaryExpr
    | left=expression op=BITAND right=expression                               # binaryExpr
    | left=expression op=CARET right=expression                                # binaryExpr
    | left=expression op=BITOR right=expression                                # binaryExpr
    | left=expression op=AND right=expression                                  # binaryExpr
    | left=expression op=OR right=expression                                   # binaryExpr
    | <assoc=right> condition=expression QUESTION whenTrue=expression COLON whenFalse=expression # conditionalExpr
    | <assoc=right> target=expression op=(ASSIGN | ADD_ASSIGN | SUB_ASSIGN | MUL_ASSIGN | DIV_ASSIGN
        | MOD_ASSIGN | AND_ASSIGN | OR_ASSIGN | XOR_ASSIGN | LSHIFT_ASSIGN | RSHIFT_ASSIGN
        | URSHIFT_ASSIGN) value=expression                                     # assignExpr
    ;

// `>>` and `>>>` are built from single `>` tokens so that `Vector<Vector<Integer>>` lexes as types do.
shiftOperator
    : LT LT
    | GT GT GT
    | GT GT
    ;

primary
    : LPAREN expression RPAREN                                                 # parenExpr
    | literal                                                                  # literalExpr
    | THIS                                                                     # thisExpr
    | DOT identifier arguments                                                 # selfInvocation
    | DOT identifier                                                           # selfAttribute
    | identifier arguments                                                     # plainCall
    | identifier                                                               # nameExpr
    | GETACCEPTSTATE LPAREN agent=expression? RPAREN                           # getAcceptStateExpr
    | GETMESSAGEFROMEVENT LPAREN event=identifier RPAREN                       # getMessageExpr
    | NEW creator                                                              # newExpr
    | primitiveType dims? DOT identifier                                       # primitiveClassLiteral
    ;

arguments
    : LPAREN expressionList? RPAREN
    ;

creator
    : createdName arguments                                                    # objectCreator
    | createdName (LBRACK expression RBRACK)+ dims?                            # arrayCreator
    | createdName dims arrayInitializer                                        # arrayLiteralCreator
    ;

createdName
    : qualifiedName typeArguments?
    | primitiveType
    ;

literal
    : IntegerLiteral
    | FloatingPointLiteral
    | CharacterLiteral
    | StringLiteral
    | TRUE
    | FALSE
    | NULL
    ;

// ---------------------------------------------------------------- types

javaType
    : primitiveType dims?
    | qualifiedName typeArguments? dims?
    ;

primitiveType
    : BOOLEAN | BYTE | CHAR | SHORT | INT | LONG | FLOAT | DOUBLE
    ;

typeArguments
    : LT typeArgument (COMMA typeArgument)* GT
    | LT GT
    ;

typeArgument
    : javaType
    | QUESTION ((EXTENDS_WORD | SUPER_WORD) javaType)?
    ;

dims
    : (LBRACK RBRACK)+
    ;

qualifiedName
    : identifier (DOT identifier)*
    ;

// Words Java reserves but MASL does not are names here (`class`, `super`, …), as MASL §2 says.
identifier
    : Identifier
    | EXTENDS_WORD
    | SUPER_WORD
    ;

// ---------------------------------------------------------------- lexer

// Reserved words of MASL §2.
IMPORT              : 'import';
AS                  : 'as';
TYPE                : 'type';
USE                 : 'use';
NEWAGENT            : 'newAgent';
ENTRY_DECL          : 'Entry';
ENTRY               : 'entry';
SCALAR              : 'scalar';
SYNCHRONOUS         : 'synchronous';
ASYNCHRONOUS        : 'asynchronous';
LOCAL               : 'local';
SHARED              : 'shared';
FINAL               : 'final';
LIMITED             : 'limited';
EVENT               : 'event';
LLABEL              : 'LLabel';
SLABEL              : 'SLabel';
REACT               : 'react';
DEFAULT             : 'default';
RESUME              : 'resume';
RESTART             : 'restart';
REELECT             : 'reelect';
BREAK               : 'break';
EXIT                : 'exit';
EMIT                : 'emit';
EMITWITHMESSAGE     : 'emitWithMessage';
GETMESSAGEFROMEVENT : 'getMessageFromEvent';
CLEAREVENTS         : 'clearEvents';
GETACCEPTSTATE      : 'getAcceptState';
SETACCEPTSTATE      : 'setAcceptState';
WAIT                : 'wait';
IF                  : 'if';
ELSE                : 'else';
WHILE               : 'while';
FOR                 : 'for';
DO                  : 'do';
LOOP                : 'loop';
NEW                 : 'new';
THIS                : 'this';
NULL                : 'null';
TRUE                : 'true';
FALSE               : 'false';

// Java words the expression and type syntax needs.
INSTANCEOF          : 'instanceof';
BOOLEAN             : 'boolean';
BYTE                : 'byte';
CHAR                : 'char';
SHORT               : 'short';
INT                 : 'int';
LONG                : 'long';
FLOAT               : 'float';
DOUBLE              : 'double';
EXTENDS_WORD        : 'extends';
SUPER_WORD          : 'super';

// Literals (Java's).
IntegerLiteral
    : DecimalNumeral IntegerSuffix?
    | HexNumeral IntegerSuffix?
    | BinaryNumeral IntegerSuffix?
    ;

FloatingPointLiteral
    : Digits DOT_CHAR Digits? ExponentPart? FloatSuffix?
    | DOT_CHAR Digits ExponentPart? FloatSuffix?
    | Digits ExponentPart FloatSuffix?
    | Digits ExponentPart? FloatSuffix
    ;

CharacterLiteral
    : '\'' (~['\\\r\n] | EscapeSequence) '\''
    ;

StringLiteral
    : '"' (~["\\\r\n] | EscapeSequence)* '"'
    ;

fragment DOT_CHAR       : '.';
fragment IntegerSuffix  : [lL];
fragment FloatSuffix    : [fFdD];
fragment DecimalNumeral : Digits;
fragment Digits         : [0-9] ([0-9_]* [0-9])?;
fragment HexNumeral     : '0' [xX] [0-9a-fA-F] ([0-9a-fA-F_]* [0-9a-fA-F])?;
fragment BinaryNumeral  : '0' [bB] [01] ([01_]* [01])?;
fragment ExponentPart   : [eE] [+-]? Digits;
fragment EscapeSequence
    : '\\' [btnfr"'\\]
    | '\\' [0-7] [0-7]? [0-7]?
    | '\\' 'u'+ [0-9a-fA-F] [0-9a-fA-F] [0-9a-fA-F] [0-9a-fA-F]
    ;

// Separators and operators (Java's, plus `<>`).
LPAREN          : '(';
RPAREN          : ')';
LBRACE          : '{';
RBRACE          : '}';
LBRACK          : '[';
RBRACK          : ']';
SEMI            : ';';
COMMA           : ',';
DOT             : '.';
DIAMOND         : '<>';
ASSIGN          : '=';
GT              : '>';
LT              : '<';
BANG            : '!';
TILDE           : '~';
QUESTION        : '?';
COLON           : ':';
EQUAL           : '==';
LE              : '<=';
GE              : '>=';
NOTEQUAL        : '!=';
AND             : '&&';
OR              : '||';
INC             : '++';
DEC             : '--';
ADD             : '+';
SUB             : '-';
MUL             : '*';
DIV             : '/';
BITAND          : '&';
BITOR           : '|';
CARET           : '^';
MOD             : '%';
ADD_ASSIGN      : '+=';
SUB_ASSIGN      : '-=';
MUL_ASSIGN      : '*=';
DIV_ASSIGN      : '/=';
AND_ASSIGN      : '&=';
OR_ASSIGN       : '|=';
XOR_ASSIGN      : '^=';
MOD_ASSIGN      : '%=';
LSHIFT_ASSIGN   : '<<=';
RSHIFT_ASSIGN   : '>>=';
URSHIFT_ASSIGN  : '>>>=';

// Letters (\p{L}) and decimal digits (\p{Nd}) of any script. Beyond ASCII they are told by Java's own
// tables in a predicate: a set of every Unicode letter costs a fresh JVM a tenth of its first
// translation to read into the lexer's ATN.
Identifier
    : IdentifierStart IdentifierPart*
    ;

fragment IdentifierStart
    : [a-zA-Z$_]
    | ~[\u0000-\u007F] {Character.isLetter(_input.LA(-1))}?
    ;

fragment IdentifierPart
    : [a-zA-Z0-9$_]
    | ~[\u0000-\u007F] {Character.isLetter(_input.LA(-1)) || Character.getType(_input.LA(-1)) == Character.DECIMAL_DIGIT_NUMBER}?
    ;

WS              : [ \t\r\n\f]+ -> channel(HIDDEN);
BLOCK_COMMENT   : '/*' .*? '*/' -> channel(HIDDEN);
LINE_COMMENT    : '//' ~[\r\n]* -> channel(HIDDEN);

// A string the line ends inside: one token, so the error names it instead of its characters one by one.
UnterminatedString
    : '"' (~["\\\r\n] | EscapeSequence)*
    ;

// Anything else is one bad character, reported by the parser with its position instead of a lexer crash.
UNEXPECTED_CHAR : . ;
