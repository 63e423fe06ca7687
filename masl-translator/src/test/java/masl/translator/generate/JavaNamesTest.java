package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** MASL names made Java names. */
class JavaNamesTest {

    @Test
    void missionIdsAreLowerCaseIdentifiersFromTheFileName() {
        assertEquals("hello", JavaNames.missionId("missions/hello.masl"));
        assertEquals("my_run_2", JavaNames.missionId("My-Run 2.masl"));
        assertEquals("_1st", JavaNames.missionId("1st.masl"));
        assertEquals("class_", JavaNames.missionId("class.masl"));
        assertEquals("_masl", JavaNames.missionId(".masl"));
    }

    @Test
    void classNamesAreCamelCase() {
        assertEquals("HelloMission", JavaNames.missionClass("hello"));
        assertEquals("MyRun2Mission", JavaNames.missionClass("my_run_2"));
        assertEquals("KheperaProgram", JavaNames.programClass("Khepera"));
    }

    @Test
    void constantsAreUpperSnakeCaseAndUniqueNamesGetANumber() {
        assertEquals("MY_BLOCK", JavaNames.constant("myBlock"));
        assertEquals("MAIN", JavaNames.constant("main"));
        JavaNames.Unique names = new JavaNames.Unique("AGENTS");
        assertEquals("AGENTS_2", names.take("AGENTS"));
        assertEquals("AB", names.take("AB"));
        assertEquals("AB_2", names.take("AB"));
    }

    @Test
    void javaKeywordsGetAnUnderscore() {
        assertEquals("class_", JavaNames.identifier("class"));
        assertEquals("speed", JavaNames.identifier("speed"));
    }
}
