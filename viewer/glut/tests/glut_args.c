/*
 * glut_args: a legacy-style GLUT demo with options of its own, built
 * twice: against the system's <GL/freeglut.h> and Debian's libglut
 * (freeglut 3.4, glutInit needs an X display), and against fixgl's
 * include/ and libfixglut (headless).  glutInit takes its own options out
 * of argv; the program then reads what is left with getopt_long and
 * prints it, with the initial window geometry and context mode glutInit
 * derived.  run_args_vs_freeglut.py runs both on the same command lines
 * and requires the same output and exit status.
 *
 *   glut-args [GLUT OPTIONS] [-f N|--frames=N] [-w|--wire] [--title T] [FILE...]
 */
#include <GL/freeglut.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
   const int given = argc;
   glutInit(&argc, argv);
   printf("glutInit left %d of %d arguments:", argc, given);
   for (int i = 1; i < argc; i++)
      printf(" [%s]", argv[i]);
   printf("\n");

   static const struct option longopts[] = {
      { "frames", required_argument, NULL, 'f' },
      { "wire", no_argument, NULL, 'w' },
      { "title", required_argument, NULL, 't' },
      { NULL, 0, NULL, 0 },
   };
   int frames = 1, wire = 0, c;
   const char *title = "glut-args";
   opterr = 0;
   while ((c = getopt_long(argc, argv, "f:wt:", longopts, NULL)) != -1) {
      switch (c) {
      case 'f': frames = atoi(optarg); break;
      case 'w': wire = 1; break;
      case 't': title = optarg; break;
      default:
         printf("the demo's parser refuses an option (optopt %d)\n", optopt);
         return 2;
      }
   }
   printf("demo: frames %d, wire %d, title \"%s\"\n", frames, wire, title);
   for (int i = optind; i < argc; i++)
      printf("demo: file [%s]\n", argv[i]);
   printf("init window: %d %d %dx%d, direct rendering %d\n", glutGet(GLUT_INIT_WINDOW_X),
          glutGet(GLUT_INIT_WINDOW_Y), glutGet(GLUT_INIT_WINDOW_WIDTH),
          glutGet(GLUT_INIT_WINDOW_HEIGHT), glutGet(GLUT_DIRECT_RENDERING));
   return 0;
}
