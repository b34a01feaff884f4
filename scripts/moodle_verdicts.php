<?php
// Ask a real Moodle what fraction it awards for GIVEN responses to imported questions.
//
// The book's Moodle XML export is imported into a throw-away Moodle with the shared harness
// (../shared/moodle: setup.sh, then import.php FILE.xml). This script then answers those questions
// through Moodle's own question engine (harness_attempt(): a fresh question usage per response,
// 'deferredfeedback' behaviour as in a quiz, submit, finish) and reports the fraction, state and
// feedback that Moodle gives. It does not decide anything itself: it only types the responses.
//
//   php scripts/moodle_verdicts.php --inputs=IN.json [--course=SHORTNAME] [--json=OUT.json]
//                                   [--xml=EXPORT.xml] [--harness=DIR] [--moodle=DIR]
//
// Options:
//   --inputs=IN.json     the responses (format below); required
//   --course=SHORTNAME   the course whose question bank holds the questions
//                        (default: the newest course import.php created, as attempt.php does)
//   --json=OUT.json      also write the report to this file
//   --xml=EXPORT.xml     the Moodle XML file that was imported: an idnumber Moodle did not store is looked up
//                        there and the question found by its name (see "Cloze idnumbers" below)
//   --harness=DIR        the shared Moodle harness, holding harnesslib.php (default /work/shared/moodle)
//   --moodle=DIR         the Moodle root (read by harnesslib.php; else $MOODLE_ROOT, else /opt/moodle-harness/www)
//
// IN.json maps a question's idnumber to a list of responses:
//   {"kin-07": [ {"label": "key 2 s.f.", "parts": [ {"number": "11.6", "unit": "m/s^2"} ]}, ... ],
//    "mc-03":  [ {"label": "wrong option", "parts": [ {"choice": "downwards"} ]} ],
//    "cloze-1": [ {"label": "all right", "parts": [ {"number": "11.6", "unit": ""}, {"choice": "upwards"} ]} ]}
// What a part means depends on Moodle's qtype:
//   numerical    one part {"number", "unit"}; "unit" may be "" or absent. With a separate unit field
//                (radio buttons / drop-down) the unit is the one selected, "" = none selected. With a unit
//                typed in the answer box it goes after the number (before it if the question puts units
//                on the left), separated by a space; "" = the number alone. If the question shows no unit
//                at all, the unit is not typed (as harnesslib's harness_numerical_response() does).
//   multichoice  one part {"choice": "<option text>"}: the option whose text, after strip_tags() and trim(),
//                equals it (case-sensitive; if none does, entities decoded and white space collapsed).
//                A multiple-answer question takes {"choice": ["a", "b"]} (every other box left empty).
//   multianswer  (Cloze) one part per sub-question, in order: {"number", "unit"} for NUMERICAL (Cloze has
//                no unit field: the unit is typed after the number, with a space, only when it is not "");
//                {"choice": "..."} for MULTICHOICE (a list for MULTIRESPONSE); {"text": "..."} for SHORTANSWER.
//                Responses go in as sub1_answer, sub2_answer, ... (sub1_choice0 ... for MULTIRESPONSE).
//   shortanswer  one part {"text"};  truefalse: one part {"choice": "True"} or {"choice": "False"}.
//
// Output (stdout, and --json): {"moodle": {...}, "course": "...", "results": {"<idnumber>": [
//   {"label", "fraction" (Moodle's fraction for the whole question, null if it gave none), "state",
//    "feedback" (plain text of the feedback shown, at most 200 characters), "response" (Moodle's summary
//    of what was typed)}, ...]}, "missing": [idnumbers not in the course], "summary": {...}}.
// A response that cannot be typed (no such option, wrong number of parts) gets fraction null, state null
// and an "error"; anything Moodle printed or raised during an attempt goes in "moodle_messages".
// Progress goes to STDERR every 200 attempts.
//
// Cloze idnumbers: Moodle 4.3.0's XML import ignores <idnumber> in a Cloze (multianswer) question
// (qformat_xml::import_multianswer() never reads it; fixed upstream by MDL-79279, after 4.3.0). Such a
// question has no idnumber in the bank, so without --xml it is reported under "missing". With --xml, the
// <question> carrying that idnumber in the file gives the name, and the one question of the course with
// that name, the same qtype and no idnumber is answered; "found_by_name" lists these.
//
// Exit status: 0 the report was made (whatever the fractions); 2 usage or set-up problem.
// Only reads Moodle: each attempt lives in memory and is never saved.

define('CLI_SCRIPT', true);

const MV_DEFAULT_HARNESS = '/work/shared/moodle';
const MV_PROGRESS_EVERY = 200;
const MV_FEEDBACK_CHARS = 200;

function mv_usage(string $problem = ''): void {
    if ($problem !== '') {
        fwrite(STDERR, "moodle_verdicts.php: $problem\n");
    }
    fwrite(STDERR, "usage: php scripts/moodle_verdicts.php --inputs=IN.json [--course=SHORTNAME] [--json=OUT.json]\n"
        . "                                   [--xml=EXPORT.xml] [--harness=DIR] [--moodle=DIR]\n");
    exit(2);
}

// Options are read before Moodle is booted: --harness says where the bootstrap code is.
$mvopts = ['inputs' => '', 'course' => '', 'json' => '', 'xml' => '', 'harness' => MV_DEFAULT_HARNESS, 'moodle' => ''];
foreach (array_slice($argv, 1) as $arg) {
    if ($arg === '--help' || $arg === '-h') {
        mv_usage();
    }
    if (!preg_match('/^--([a-z]+)=(.*)$/s', $arg, $m) || !array_key_exists($m[1], $mvopts)) {
        mv_usage("unrecognised argument '$arg'");
    }
    $mvopts[$m[1]] = $m[2];
}
if ($mvopts['inputs'] === '') {
    mv_usage('--inputs=IN.json is required');
}

/**
 * Read and check IN.json before booting Moodle, so a malformed file fails fast.
 * @return array idnumber => list of ['label' => string, 'parts' => list of arrays]
 */
function mv_read_inputs(string $file): array {
    if (!is_readable($file)) {
        mv_usage("cannot read --inputs file '$file'");
    }
    $data = json_decode((string) file_get_contents($file), true);
    if (!is_array($data) || ($data && array_is_list($data))) {
        mv_usage("--inputs '$file' must hold a JSON object {\"<idnumber>\": [responses]}"
            . (json_last_error() ? ' (' . json_last_error_msg() . ')' : ''));
    }
    $inputs = [];
    foreach ($data as $idnumber => $list) {
        $idnumber = (string) $idnumber;
        if (!is_array($list) || !array_is_list($list)) {
            mv_usage("--inputs: the value for '$idnumber' must be a list of responses");
        }
        foreach ($list as $k => $input) {
            $where = "--inputs: '$idnumber' response " . ($k + 1);
            if (!is_array($input) || !isset($input['parts']) || !is_array($input['parts'])
                    || !array_is_list($input['parts'])) {
                mv_usage("$where must be an object with a list \"parts\"");
            }
            foreach ($input['parts'] as $j => $part) {
                if (!is_array($part) || array_is_list($part) && $part !== []) {
                    mv_usage("$where part " . ($j + 1) . ' must be an object such as {"number": "11.6", "unit": "N"}');
                }
                foreach (['number', 'unit', 'text'] as $key) {
                    if (isset($part[$key]) && !is_scalar($part[$key])) {
                        mv_usage("$where part " . ($j + 1) . ": \"$key\" must be a string");
                    }
                }
            }
            $inputs[$idnumber][] = ['label' => (string) ($input['label'] ?? ('response ' . ($k + 1))),
                'parts' => $input['parts']];
        }
        $inputs[$idnumber] ??= [];
    }
    return $inputs;
}

/**
 * idnumber => ['name' => raw name, 'type' => type attribute] of every question in a Moodle XML file.
 */
function mv_read_xml_names(string $file): array {
    if (!is_readable($file)) {
        mv_usage("cannot read --xml file '$file'");
    }
    libxml_use_internal_errors(true);
    $xml = simplexml_load_file($file, 'SimpleXMLElement', LIBXML_NONET | LIBXML_PARSEHUGE | LIBXML_NOCDATA);
    if ($xml === false) {
        $err = libxml_get_errors()[0] ?? null;
        mv_usage("--xml '$file' is not well-formed XML" . ($err ? ' (line ' . $err->line . ': ' . trim($err->message) . ')' : ''));
    }
    $names = [];
    foreach ($xml->question as $q) {
        $idnumber = trim((string) $q->idnumber);
        if ($idnumber !== '' && (string) $q['type'] !== 'category') {
            $names[$idnumber] = ['name' => trim((string) $q->name->text), 'type' => (string) $q['type']];
        }
    }
    return $names;
}

$mvinputs = mv_read_inputs($mvopts['inputs']);
$mvxmlnames = $mvopts['xml'] !== '' ? mv_read_xml_names($mvopts['xml']) : null;
if ($mvopts['json'] !== '' && !is_writable(dirname($mvopts['json']) ?: '.')) {
    mv_usage("cannot write --json file '{$mvopts['json']}' (its directory is not writable)");
}
$mvharness = rtrim($mvopts['harness'], '/');
if (!is_readable($mvharness . '/harnesslib.php')) {
    mv_usage("no harnesslib.php in --harness directory '$mvharness' (the shared Moodle harness, see its README.md)");
}

// Boots Moodle (config.php of the harness site; it reads --moodle= from $argv itself, exits 2 if there is none).
// Must be required at the top level: config.php sets up $CFG, $DB and friends as globals.
require($mvharness . '/harnesslib.php');
require_once($CFG->dirroot . '/question/type/numerical/questiontype.php');

/** Thrown when a given response cannot be typed into the question (reported per response, not fatal). */
class mv_input_error extends Exception {
}

/** Option text as the inputs give it: HTML stripped, trimmed. */
function mv_option_text(string $html): string {
    $text = trim(strip_tags($html));
    // a sketch-graph option is an image: it reads as its alt text (the shape in words)
    if ($text === '' && preg_match('/<img[^>]*\balt="([^"]*)"/', $html, $m)) {
        return trim(html_entity_decode($m[1], ENT_QUOTES | ENT_HTML5, 'UTF-8'));
    }
    return $text;
}

/** A looser form of the same text: entities decoded, white space (and non-breaking spaces) collapsed. */
function mv_loose_text(string $text): string {
    $text = html_entity_decode(strip_tags($text), ENT_QUOTES | ENT_HTML5, 'UTF-8');
    return trim(preg_replace('/[\s\x{00A0}]+/u', ' ', $text));
}

/**
 * The answer id of the option whose text is $choice.
 * @param array $answers answer id => question_answer
 */
function mv_find_option(array $answers, $choice, string $where): int {
    if (!is_string($choice) && !is_numeric($choice)) {
        throw new mv_input_error("$where: \"choice\" must be the text of an option");
    }
    $choice = (string) $choice;
    foreach (['mv_option_text', 'mv_loose_text'] as $normalise) {
        $want = $normalise($choice);
        $hits = array_keys(array_filter($answers, fn($a) => $normalise((string) $a->answer) === $want));
        if (count($hits) === 1) {
            return (int) $hits[0];
        }
        if (count($hits) > 1) {
            throw new mv_input_error("$where: " . count($hits) . " options read '$want'; cannot tell which one is meant");
        }
    }
    $texts = array_map(fn($a) => '"' . mv_option_text((string) $a->answer) . '"', $answers);
    throw new mv_input_error("$where: no option reads \"$choice\" (the options are " . implode(', ', $texts) . ')');
}

/** The list of choices of a part: a string, or a list of strings for a multiple-answer question. */
function mv_choices(array $part, bool $multi, string $where): array {
    if (!array_key_exists('choice', $part)) {
        throw new mv_input_error("$where: a multiple-choice part needs {\"choice\": \"<option text>\"}");
    }
    $c = $part['choice'];
    if (is_array($c)) {
        if (!$multi && count($c) !== 1) {
            throw new mv_input_error("$where: only one option can be chosen in a single-answer question");
        }
        return array_values($c);
    }
    return [$c];
}

/** The number of a numerical part, as a string, and its unit ('' when none). */
function mv_number_and_unit(array $part, string $where): array {
    if (!array_key_exists('number', $part)) {
        throw new mv_input_error("$where: a numerical part needs {\"number\": \"...\", \"unit\": \"...\"}");
    }
    return [trim((string) $part['number']), trim((string) ($part['unit'] ?? ''))];
}

/**
 * Plan how to type one given response into this question: returns fn(question_definition, question_attempt): array
 * for harness_attempt(). Everything that can be checked against the stored question is checked here; only the
 * option order (which is per attempt) is looked up when the attempt has started.
 */
function mv_plan_response(question_definition $qdef, array $parts): callable {
    $qtype = $qdef->get_type_name();
    $nparts = count($parts);
    $one = function() use ($qtype, $nparts) {
        if ($nparts !== 1) {
            throw new mv_input_error("a $qtype question takes exactly one part, $nparts given");
        }
    };

    switch ($qtype) {
        case 'numerical':
            $one();
            [$number, $unit] = mv_number_and_unit($parts[0], 'part 1');
            return function($q) use ($number, $unit) {
                if ($unit === '') {                  // No unit given: the number alone, nothing selected.
                    return $q->has_separate_unit_field() ? ['answer' => $number, 'unit' => ''] : ['answer' => $number];
                }
                if ($q->unitdisplay == qtype_numerical::UNITINPUT && $q->ap->get_default_unit() === null) {
                    return ['answer' => $number . ' ' . $unit];   // Unit box with no units defined: typed as given.
                }
                return harness_numerical_response($q, $number, $unit);
            };

        case 'multichoice':
            $one();
            $multi = !($qdef instanceof qtype_multichoice_single_question);
            $ansids = array_map(fn($c) => mv_find_option($qdef->answers, $c, 'part 1'),
                mv_choices($parts[0], $multi, 'part 1'));
            return function($q, $qa) use ($ansids, $multi) {
                $order = $q->get_order($qa);
                $response = [];
                foreach ($ansids as $ansid) {
                    $pos = array_search($ansid, $order);
                    if ($multi) {
                        $response['choice' . $pos] = 1;
                    } else {
                        $response['answer'] = $pos;
                    }
                }
                return $response;
            };

        case 'truefalse':
            $one();
            $c = mv_choices($parts[0], false, 'part 1')[0];
            $value = ['true' => 1, 'false' => 0][strtolower(mv_loose_text((string) $c))] ?? null;
            if ($value === null) {
                throw new mv_input_error("part 1: a true/false question takes {\"choice\": \"True\"} or \"False\"");
            }
            return fn($q) => ['answer' => $value];

        case 'shortanswer':
            $one();
            $text = (string) ($parts[0]['text'] ?? $parts[0]['choice'] ?? '');
            return fn($q) => ['answer' => $text];

        case 'multianswer':
            $subs = $qdef->subquestions;   // Keyed 1, 2, ... in the order of the text.
            if ($nparts !== count($subs)) {
                throw new mv_input_error("this Cloze question has " . count($subs) . " sub-questions, $nparts parts given");
            }
            $steps = [];                   // Per sub-question: fn($q, $qa) => [response key => value].
            foreach (array_values($subs) as $k => $sub) {
                $i = array_keys($subs)[$k];
                $part = $parts[$k];
                $where = 'part ' . ($k + 1);
                $key = "sub{$i}_";
                if ($sub instanceof qtype_numerical_question) {
                    [$number, $unit] = mv_number_and_unit($part, $where);
                    $typed = $unit === '' ? $number : $number . ' ' . $unit;
                    $steps[] = fn($q, $qa) => [$key . 'answer' => $typed];
                } else if ($sub instanceof qtype_multichoice_base) {
                    $multi = !($sub instanceof qtype_multichoice_single_question);
                    $ansids = array_map(fn($c) => mv_find_option($sub->answers, $c, $where),
                        mv_choices($part, $multi, $where));
                    $steps[] = function($q, $qa) use ($i, $ansids, $multi, $key) {
                        $order = $q->subquestions[$i]->get_order($qa);   // Set when the attempt started.
                        $r = [];
                        foreach ($ansids as $ansid) {
                            $pos = array_search($ansid, $order);
                            if ($multi) {
                                $r[$key . 'choice' . $pos] = 1;
                            } else {
                                $r[$key . 'answer'] = $pos;
                            }
                        }
                        return $r;
                    };
                } else if ($sub instanceof qtype_shortanswer_question) {
                    $text = (string) ($part['text'] ?? $part['choice'] ?? $part['number'] ?? '');
                    $steps[] = fn($q, $qa) => [$key . 'answer' => $text];
                } else {
                    throw new mv_input_error("$where: sub-question type " . get_class($sub) . ' is not supported');
                }
            }
            return function($q, $qa) use ($steps) {
                $response = [];
                foreach ($steps as $step) {
                    $response += $step($q, $qa);
                }
                return $response;
            };

        default:
            throw new mv_input_error("qtype '$qtype' is not supported (numerical, multichoice, multianswer, "
                . "shortanswer, truefalse are)");
    }
}

// ------------------------------------------------------------------------------------------ main -----

$course = $mvopts['course'] !== '' ? $DB->get_record('course', ['shortname' => $mvopts['course']]) : harness_latest_course();
if (!$course) {
    fwrite(STDERR, 'moodle_verdicts.php: ' . ($mvopts['course'] !== ''
        ? "no course with shortname '{$mvopts['course']}'"
        : 'no course made by import.php yet (import the questions first: php '
            . $mvharness . '/import.php FILE.xml)') . "\n");
    exit(2);
}

// idnumber => question id (latest version) in the course's question bank.
$byidnumber = [];
$warnings = [];
$noidnumber = [];                 // Questions Moodle stored without an idnumber, for --xml.
foreach (harness_questions_in_contexts([context_course::instance($course->id)->id]) as $q) {
    if ($q->idnumber === null || $q->idnumber === '') {
        $noidnumber[] = $q;
        continue;
    }
    if (isset($byidnumber[$q->idnumber])) {
        $warnings[] = "idnumber '{$q->idnumber}' is used by questions {$byidnumber[$q->idnumber]} and {$q->id} "
            . "(in different categories); answering the newer, {$q->id}";
    }
    $byidnumber[$q->idnumber] = (int) $q->id;
}

// Idnumbers Moodle did not keep (Cloze in 4.3.0): the file names the question, the name finds it.
$foundbyname = [];
if ($mvxmlnames !== null) {
    $xmlformat = new qformat_xml();
    $qtypeof = ['cloze' => 'multianswer'];
    foreach (array_keys($mvinputs) as $idnumber) {
        if (isset($byidnumber[$idnumber]) || !isset($mvxmlnames[$idnumber])) {
            continue;
        }
        $infile = $mvxmlnames[$idnumber];
        $name = $xmlformat->clean_question_name($infile['name']);
        $qtype = $qtypeof[$infile['type']] ?? $infile['type'];
        $hits = array_values(array_filter($noidnumber, fn($q) => $q->name === $name && $q->qtype === $qtype));
        if (!$hits) {
            continue;
        }
        if (count($hits) > 1) {
            $warnings[] = "idnumber '$idnumber': " . count($hits) . " $qtype questions without an idnumber are named "
                . "'$name'; answering the newest, " . end($hits)->id;
        }
        $byidnumber[$idnumber] = (int) end($hits)->id;
        $foundbyname[$idnumber] = ['id' => (int) end($hits)->id, 'name' => $name];
    }
}

$report = [
    'harness' => 'scripts/moodle_verdicts.php',
    'moodle' => harness_moodle_info(),
    'course' => $course->shortname,
    'behaviour' => 'deferredfeedback',
    'results' => [],
    'missing' => [],
];
harness_take_php_messages('bootstrap');

$total = array_sum(array_map('count', $mvinputs));
$done = 0;
$errors = 0;
$started = microtime(true);
foreach ($mvinputs as $idnumber => $inputs) {
    if (!isset($byidnumber[$idnumber])) {
        $report['missing'][] = $idnumber;
        continue;
    }
    $questionid = $byidnumber[$idnumber];
    try {
        $qdef = question_bank::load_question($questionid);   // Once per question; harness_attempt() reuses the cache.
    } catch (Throwable $e) {
        $qdef = null;
        $loaderror = 'Moodle cannot load question ' . $questionid . ': ' . get_class($e) . ': ' . $e->getMessage();
    }
    $rows = [];
    foreach ($inputs as $input) {
        $row = ['label' => $input['label'], 'fraction' => null, 'state' => null, 'feedback' => ''];
        ob_start();                                          // Keep stdout for the JSON report.
        try {
            if (!$qdef) {
                throw new mv_input_error($loaderror);
            }
            $r = harness_attempt($questionid, mv_plan_response($qdef, $input['parts']));
            $row['fraction'] = $r['fraction'];
            $row['state'] = $r['state'];
            $row['feedback'] = core_text::substr($r['feedback_shown'] ?? '', 0, MV_FEEDBACK_CHARS);
            $row['response'] = $r['response_summary'] === null ? null : trim($r['response_summary']);
            if (isset($r['render_error'])) {
                $row['render_error'] = $r['render_error'];
            }
        } catch (mv_input_error $e) {
            $row['error'] = $e->getMessage();
            $errors++;
        } catch (Throwable $e) {
            $row['error'] = 'Moodle raised ' . get_class($e) . ': ' . $e->getMessage();
            $errors++;
        }
        $printed = trim((string) ob_get_clean());
        $msgs = array_values(array_filter(harness_take_php_messages('attempt'), fn($m) => $m['kind'] !== 'php_deprecated'));
        if ($printed !== '') {
            $msgs[] = ['kind' => 'output', 'stage' => 'attempt', 'text' => harness_text($printed, 300)];
        }
        if ($msgs) {
            $row['moodle_messages'] = $msgs;
        }
        $rows[] = $row;
        if (++$done % MV_PROGRESS_EVERY === 0) {
            fprintf(STDERR, "moodle_verdicts: %d/%d attempts, %.1f s, %d MB\n", $done, $total,
                microtime(true) - $started, memory_get_usage(true) >> 20);
        }
    }
    $report['results'][$idnumber] = $rows;
}

if ($foundbyname) {
    $report['found_by_name'] = $foundbyname;
}
if ($report['missing'] && $mvxmlnames === null && $noidnumber) {
    $warnings[] = count($noidnumber) . ' question(s) of the course have no idnumber (Moodle 4.3.0 drops it from '
        . 'Cloze questions on import); pass --xml=EXPORT.xml to find missing ones by name';
}
$report['summary'] = [
    'questions' => count($report['results']),
    'attempts' => $done,
    'responses_not_typed' => $errors,
    'missing' => count($report['missing']),
    'seconds' => round(microtime(true) - $started, 2),
];
if ($warnings) {
    $report['warnings'] = $warnings;
}
harness_emit($report, $mvopts['json'] !== '' ? $mvopts['json'] : null);
exit(0);
