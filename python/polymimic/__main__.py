from polymimic.cli import main

main()
