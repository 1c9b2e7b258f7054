//! Reading characters, words and numbers: the lexer's messages, the
//! program's size and the diagnostics limit.

use super::templates;

templates! {
    BLOCK_TOO_LONG = BlockTooLong:
        "block of {n} characters is longer than the limit of {limit} (setting limits.block_chars); it is skipped",
        "程序段有 {n} 个字符，超过上限 {limit}（设置 limits.block_chars），该段跳过";
    UNMATCHED_PAREN = UnmatchedParen:
        "')' without an opening '('",
        "')' 之前没有对应的 '('";
    UNSUPPORTED_MACRO = UnsupportedMacro:
        "'{c}': macro variables and expressions are not interpreted; the block is skipped",
        "'{c}'：不解释宏变量和表达式，该程序段跳过";
    NUMBER_WITHOUT_ADDRESS = UnexpectedCharacter:
        "number '{text}' without an address letter",
        "数字 '{text}' 前没有地址字母";
    UNEXPECTED_CHARACTER = UnexpectedCharacter:
        "unexpected character '{c}' (U+{hex})",
        "无法识别的字符 '{c}'（U+{hex}）";
    FULL_WIDTH = FullWidth:
        "full-width characters read as ASCII: '{original}' as '{folded}'",
        "全角字符按半角读入：'{original}' 读作 '{folded}'";
    UNCLOSED_COMMENT = UnclosedComment:
        "comment '(' is not closed on this line",
        "注释的 '(' 在本行没有闭合";
    NESTED_COMMENT = NestedComment:
        "'(' inside a comment: comments do not nest, the comment ends at the first ')'",
        "注释内又有 '('：注释不能嵌套，注释在第一个 ')' 处结束";
    CODE_AFTER_SEMICOLON = CodeAfterSemicolon:
        "'{text}' follows ';' (end of block) and is read as a comment, not executed",
        "'{text}' 在 ';'（程序段结束）之后，按注释读入，不执行";
    MALFORMED_PROGRAM_NUMBER = MalformedProgramNumber:
        "'{text}' is not a program number (O followed by up to four digits)",
        "'{text}' 不是程序号（O 后跟最多四位数字）";
    UNKNOWN_ADDRESS = UnknownAddress:
        "'{letter}' is not an address of the {controller} controller",
        "'{letter}' 不是 {controller} 系统的地址";
    MISSING_VALUE = MissingValue:
        "address '{letter}' has no value",
        "地址 '{letter}' 后没有数值";
    MALFORMED_NUMBER = MalformedNumber:
        "'{text}' is not a number",
        "'{text}' 不是合法的数值";
    TOO_MANY_DIGITS = TooManyDigits:
        "{n} significant digits: the controller accepts at most {limit} (setting limits.digits)",
        "有效数字 {n} 位：系统最多接受 {limit} 位（设置 limits.digits）";
    SECOND_SPINDLE = RepeatedWord:
        "second spindle selection in one block (first at {first})",
        "同一程序段内第二次选择主轴（第一次为 {first}）";
    SECOND_SEQUENCE_NUMBER = RepeatedWord:
        "second sequence number in one block (first at {first})",
        "同一程序段内有第二个顺序号（第一个为 {first}）";
    REPEATED_ADDRESS = RepeatedWord:
        "address {letter} appears twice in one block ({first} and {second})",
        "地址 {letter} 在同一程序段内出现两次（{first} 和 {second}）";
    PROGRAM_TOO_LARGE = ProgramTooLarge:
        "the program is {bytes} bytes, larger than the limit of {limit} (setting limits.program_bytes)",
        "程序有 {bytes} 字节，超过上限 {limit}（设置 limits.program_bytes）";
    MORE_DIAGNOSTICS = MoreDiagnostics:
        "{n} more diagnostics from here on are not shown (setting limits.diagnostics)",
        "从此处起还有 {n} 条诊断未列出（设置 limits.diagnostics）";
}
