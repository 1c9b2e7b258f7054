//! Running a program: macro lines, variables, jumps, calls and loops.

use super::{phrases, templates};

templates! {
    MACRO_SYNTAX = MacroSyntax:
        "macro statement: found {found}, expected {expected}",
        "宏语句：此处为“{found}”，应为 {expected}";
    BAD_VARIABLE_NUMBER = MacroValue:
        "variable number {value} is not a whole number",
        "变量号 {value} 不是整数";
    DIVIDED_BY_ZERO = MacroValue:
        "division by zero",
        "除数为零";
    MACRO_DOMAIN = MacroValue:
        "{what}: {value} is outside the function's domain",
        "{what}：{value} 超出函数的定义域";
    VARIABLE_OUT_OF_RANGE = MacroVariable:
        "#{n} is not a variable of the {controller} controller",
        "#{n} 不是 {controller} 系统的变量";
    VARIABLE_NOT_WRITABLE = MacroVariable:
        "#{n} cannot be written on the {controller} controller",
        "{controller} 系统不能写入 #{n}";
    SYSTEM_VARIABLE = MacroVariable:
        "system variable #{n} is not known to the preview (it reads {supported})",
        "预览不支持系统变量 #{n}（支持 {supported}）";
    NAMED_NOT_DEFINED = MacroVariable:
        "Named parameter #<{name}> not defined",
        "LinuxCNC 报警“Named parameter #<{name}> not defined”（命名参数未定义）";
    PARAMETER_RANGE = MacroVariable:
        "Parameter number out of range",
        "LinuxCNC 报警“Parameter number out of range”（参数号超出范围）";
    PROGRAM_NOT_FOUND = JumpTarget:
        "program O{n} is not in the text {setting}",
        "文本中没有程序 O{n} {setting}";
    BAD_PROGRAM_NUMBER = JumpTarget:
        "{value} is not a program number",
        "{value} 不是程序号";
    SEQUENCE_NOT_FOUND = JumpTarget:
        "sequence number N{n} is not in this program",
        "本程序中没有顺序号 N{n}";
    BAD_SEQUENCE_NUMBER = JumpTarget:
        "{value} is not a sequence number (1 to 99999)",
        "{value} 不是顺序号（1 至 99999）";
    LOOP_WITHOUT_END = JumpTarget:
        "DO{m} has no END{m} after it in this program",
        "DO{m} 之后本程序中没有 END{m}";
    END_WITHOUT_DO = JumpTarget:
        "END{m} without an open DO{m}",
        "END{m} 之前没有对应的 DO{m}";
    LOOP_NUMBER = JumpTarget:
        "loop number {m}: DO and END take 1 to {max}",
        "循环号 {m}：DO 和 END 只能用 1 至 {max}";
    CALL_NEEDS_P = JumpTarget:
        "{word} needs P, the program to call",
        "{word} 需要 P 指定被调用的程序";
    SUB_NOT_FOUND = JumpTarget:
        "{label}: the subroutine is not in the text",
        "文本中没有子程序“{label}”";
    OWORD_UNMATCHED = JumpTarget:
        "{label}: no matching {what}",
        "“{label}”：没有对应的“{what}”";
    RETURN_OUTSIDE_SUB = JumpTarget:
        "{label}: return or endsub outside a subroutine",
        "“{label}”：在子程序之外返回";
    LCNC_TOO_DEEP = CallDepth:
        "Too many subroutine levels ({what}: {limit}, {source})",
        "LinuxCNC 报警“Too many subroutine levels”（“{what}”：{limit} 层，{source}）";
    LCNC_DIVIDE_BY_ZERO = MacroValue:
        "Attempt to divide by zero",
        "LinuxCNC 报警“Attempt to divide by zero”（除数为零）";
    LCNC_NOT_A_NUMBER = MacroValue:
        "Calculation resulted in 'not a number' (MOD 0)",
        "LinuxCNC 报警“Calculation resulted in 'not a number'”（对 0 取模）";
    LCNC_SUB_SOUGHT = JumpTarget:
        "EOF seeking o-word: {label} from line: {line} (a subroutine is known once reading has passed its definition, or found after the call)",
        "LinuxCNC 报警“EOF seeking o-word: {label} from line: {line}”（子程序须在调用之前定义，或在调用之后的文本中）";
    LCNC_SUB_ILLEGAL = JumpTarget:
        "line:{line} sub: {label} found in illegal location (its definition was already read when it was called)",
        "LinuxCNC 报警“line:{line} sub: {label} found in illegal location”（调用时已读过该定义）";
    LCNC_BREAK_NOT_LOOP = JumpTarget:
        "{line}: no matching while/do label: '{block}' (found 'repeat' in line {found})",
        "LinuxCNC 报警“{line}: no matching while/do label: '{block}' (found 'repeat' in line {found})”";
    CALL_TOO_DEEP = CallDepth:
        "{what}: calls nested deeper than {limit} ({source})",
        "{what}：调用嵌套超过 {limit} 层（{source}）";
    BLOCK_LIMIT = BlockLimit:
        "more than {limit} blocks run again by loops, jumps and calls ({setting}): reading stops here",
        "循环、跳转和调用重复执行的程序段超过 {limit} 段（{setting}）：在此停止";
    MACRO_ALARM = MacroAlarm:
        "#3000 = {value}: the program raises its own alarm {value} and stops",
        "#3000 = {value}：程序发出自定义报警 {value} 并停止";
    H_ALARM = MacroAlarm:
        "G65 H99 P{n}: the program raises alarm {value} (500 + P) and stops",
        "G65 H99 P{n}：程序发出报警 {value}（500 + P）并停止";
    H_UNKNOWN = MacroSyntax:
        "G65 H{h}: not an operation of the {controller} (H01–H05, H11–H13, H21–H27, H31–H34, H80–H86, H99)",
        "G65 H{h}：{controller} 没有此运算（H01–H05、H11–H13、H21–H27、H31–H34、H80–H86、H99）";
    H_NEEDS = MacroSyntax:
        "G65 H{h} needs {what}",
        "G65 H{h} 需要 {what}";
    MAIN_REPEATS = MainRepeats:
        "M99 in the main program starts it again forever: previewed {runs} time(s) ({setting})",
        "主程序中的 M99 使程序无限重复：预览执行 {runs} 次（{setting}）";
    SUB_RUNS_OFF = SubprogramEnd:
        "the subprogram ends without M99 (or endsub): back to the caller here",
        "子程序没有以返回指令（M99）结束：在此返回调用处";
}

phrases! {
    X_VALUE: "a value", "数值";
    X_VARIABLE_NUMBER: "a variable number", "变量号";
    X_NAME: "a name", "名称";
    X_NUMBER: "a number", "数字";
    X_FEWER_BRACKETS: "fewer nested brackets", "更少的嵌套括号";
    X_FUNCTION: "a function or value", "函数或数值";
    X_ATAN_DIVISOR: "[ after ATAN[…]/", "ATAN[…]/ 之后的 [";
    X_ATAN_SLASH: "/ after ATAN[…]", "ATAN[…] 之后的 /";
    X_END: "end of block", "程序段结束";
    X_LOOP: "a loop number", "循环号";
    X_GOTO_THEN: "GOTO or THEN", "GOTO 或 THEN";
    X_DO: "DO", "DO";
    X_ADDRESS: "an address", "地址";
    X_OWN_ADDRESS: "an address of this controller", "本系统的地址";
    X_OWORD_NUMBER: "an o-word number", "o 字编号";
    X_OWORD_KEYWORD: "an o-word keyword (sub, call, if, while …)", "o 字关键字";
    X_VAR: "#n", "#n";
    X_H_RESULT: "its result variable P#i", "结果变量 P#i";
    X_H_SEQUENCE: "the sequence number P of its jump", "跳转目标顺序号 P";
    X_H_OPERANDS: "its operands Q and R", "运算数 Q 和 R";
    X_H_ALARM: "the alarm number P", "报警号 P";
    X_OPEN: "[", "[";
    X_CLOSE: "]", "]";
    X_EQUALS: "=", "=";
    X_COMMA: ",", ",";
    X_HASH: "#", "#";
    X_LT: "<", "<";
    X_GT: ">", ">";
}
