<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>armtrack::app::gui::LiveTrunkFeedback</name>
    <message numerus="yes">
        <source>%n repetition(s) with compensation</source>
        <translation>
            <numerusform>%n repetition with compensation</numerusform>
            <numerusform>%n repetitions with compensation</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::app::gui::SensorCalibrationPage</name>
    <message numerus="yes">
        <source>Hold still: %n s</source>
        <translation>
            <numerusform>Hold still: %n s</numerusform>
            <numerusform>Hold still: %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Move: %n s</source>
        <translation>
            <numerusform>Move: %n s</numerusform>
            <numerusform>Move: %n s</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::AppController</name>
    <message numerus="yes">
        <source>%n earlier session(s) analysed</source>
        <translation>
            <numerusform>%n earlier session analysed</numerusform>
            <numerusform>%n earlier sessions analysed</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::FirstRunScreen</name>
    <message numerus="yes">
        <source>at least %n characters</source>
        <translation>
            <numerusform>at least %n character</numerusform>
            <numerusform>at least %n characters</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The password needs at least %n characters.</source>
        <translation>
            <numerusform>The password needs at least %n character.</numerusform>
            <numerusform>The password needs at least %n characters.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::PatientScreen</name>
    <message numerus="yes">
        <source>%n stored length(s) could not be read.</source>
        <translation>
            <numerusform>%n stored length could not be read.</numerusform>
            <numerusform>%n stored lengths could not be read.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Progress report written: %1 (%n page(s)).</source>
        <translation>
            <numerusform>Progress report written: %1 (%n page).</numerusform>
            <numerusform>Progress report written: %1 (%n pages).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::ReviewScreen</name>
    <message numerus="yes">
        <source>%n repetition(s) could not be read.</source>
        <translation>
            <numerusform>%n repetition could not be read.</numerusform>
            <numerusform>%n repetitions could not be read.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Session report written: %1 (%n page(s)).</source>
        <translation>
            <numerusform>Session report written: %1 (%n page).</numerusform>
            <numerusform>Session report written: %1 (%n pages).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) on %1 (%2 full, %3 partial). Smoothness: SPARC %4, LDLJ %5.</source>
        <translation>
            <numerusform>%n repetition on %1 (%2 full, %3 partial). Smoothness: SPARC %4, LDLJ %5.</numerusform>
            <numerusform>%n repetitions on %1 (%2 full, %3 partial). Smoothness: SPARC %4, LDLJ %5.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SessionSetupPage</name>
    <message numerus="yes">
        <source>Trains %1, target %L2–%L3°, %n repetition(s).</source>
        <translation>
            <numerusform>Trains %1, target %L2–%L3°, %n repetition.</numerusform>
            <numerusform>Trains %1, target %L2–%L3°, %n repetitions.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::SignInScreen</name>
    <message numerus="yes">
        <source>Wait %n s</source>
        <translation>
            <numerusform>Wait %n s</numerusform>
            <numerusform>Wait %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Too many wrong passwords for this account: wait %n s, then try again.</source>
        <translation>
            <numerusform>Too many wrong passwords for this account: wait %n second, then try again.</numerusform>
            <numerusform>Too many wrong passwords for this account: wait %n seconds, then try again.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::ExerciseScreen</name>
    <message numerus="yes">
        <source>Then press Start: %n set(s) of %1 repetitions.</source>
        <translation>
            <numerusform>Then press Start: %n set of %1 repetitions.</numerusform>
            <numerusform>Then press Start: %n sets of %1 repetitions.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n repetition(s) leaning too far</source>
        <translation>
            <numerusform>%n repetition leaning too far</numerusform>
            <numerusform>%n repetitions leaning too far</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeConnectScreen</name>
    <message numerus="yes">
        <source>%n session(s) waiting to be sent</source>
        <translation>
            <numerusform>%n session waiting to be sent</numerusform>
            <numerusform>%n sessions waiting to be sent</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeStartScreen</name>
    <message numerus="yes">
        <source>%1: %n set(s) of %2 repetitions, %3 s rest</source>
        <translation>
            <numerusform>%1: %n set of %2 repetitions, %3 s rest</numerusform>
            <numerusform>%1: %n sets of %2 repetitions, %3 s rest</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::gui::home::HomeSummaryScreen</name>
    <message numerus="yes">
        <source>%n repetition(s) leaning too far</source>
        <translation>
            <numerusform>%n repetition leaning too far</numerusform>
            <numerusform>%n repetitions leaning too far</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::reports</name>
    <message numerus="yes">
        <source>... %n more</source>
        <translation>
            <numerusform>... %n more</numerusform>
            <numerusform>... %n more</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1: %2, target %3 to %4 deg, %n repetitions</source>
        <translation>
            <numerusform>%1: %2, target %3 to %4 deg, %n repetition</numerusform>
            <numerusform>%1: %2, target %3 to %4 deg, %n repetitions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n repetitions counted on %1: %2 full, %3 partial (judged against a reference range of %4 deg); %5 cut by the start or end of the recording and not counted.</source>
        <translation>
            <numerusform>%n repetition counted on %1: %2 full, %3 partial (judged against a reference range of %4 deg); %5 cut by the start or end of the recording and not counted.</numerusform>
            <numerusform>%n repetitions counted on %1: %2 full, %3 partial (judged against a reference range of %4 deg); %5 cut by the start or end of the recording and not counted.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>armtrack::ui::RepetitionCounterWidget</name>
    <message numerus="yes">
        <source>%n partial</source>
        <translation>
            <numerusform>%n partial</numerusform>
            <numerusform>%n partial</numerusform>
        </translation>
    </message>
</context>
</TS>
